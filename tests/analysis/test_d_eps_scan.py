#!/usr/bin/env python3
"""bench/gpu/d_eps_scan.py (issue 41's D(eps) scan), pure Python: the places rule, D per place with
its jackknife error on random walks of known D, the censoring of unresolved and non-linear runs,
the law's exponent recovered from synthetic data of a known a within its stated interval (and a
power law not excluded when the data follow one), the step-size comparison, the Fisher estimate
of the 16-place design.   python3 tests/analysis/test_d_eps_scan.py"""
import csv
import gzip
import math
import os
import random
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench", "gpu"))
import d_eps_scan as ds  # noqa: E402


def temp_dir(case):
    t = tempfile.TemporaryDirectory()
    case.addCleanup(t.cleanup)
    return t.name


def synthetic(case, args):
    d = temp_dir(case)
    argv = []
    for k, v in args.items():
        argv += [f"--{k}", str(v)]
    o, _ = ds.options(argv + ["--out", d])
    ds.cmd_synthetic(o)
    return [os.path.join(d, x) for x in sorted(os.listdir(d))]


class Places(unittest.TestCase):
    def test_rule(self):
        cs = ds.places(128)
        self.assertEqual(len(cs), 128)
        self.assertEqual(cs, sorted(cs))
        self.assertTrue(0.15 <= cs[0] and cs[-1] <= 0.48)
        for c in cs:  # none within the margins of a crossing p/q, q <= 7
            for q, r in ds.EXCLUDE.items():
                for p in range(q + 1):
                    self.assertGreaterEqual(abs(c - p / q), r - 1e-6, (c, p, q))
        # equal steps of the allowed length: 0.2 / 128 between neighbours in one piece
        steps = [b - a for a, b in zip(cs, cs[1:]) if b - a < 0.005]
        self.assertAlmostEqual(min(steps), 0.2 / 128, delta=2e-6)
        self.assertAlmostEqual(max(steps), 0.2 / 128, delta=2e-6)

    def test_candidates_on_the_energy(self):
        cand = ds.candidates(0.002, [0.3])
        self.assertEqual(len(cand), ds.per_place())
        for i1, i2, i3 in cand:
            self.assertAlmostEqual((i1 * i1 + i2 * i2) / 2 + i3 + 0.002 / 7, 0.5, delta=1e-15)
            self.assertLessEqual(abs(i1 - i2) / 2, 2e-5 * (1 + 1e-12))

    def test_choose(self):
        fli = [5.0] * 300 + [50.0] * 212  # 212 chaotic
        idx, n = ds.choose(fli)
        self.assertEqual(n, 212)
        self.assertEqual(len(idx), ds.ORBITS)
        self.assertTrue(all(fli[i] >= ds.chaotic_threshold() for i in idx))
        self.assertEqual(len(set(idx)), ds.ORBITS)
        thin = [5.0 + 0.001 * i for i in range(500)] + [40.0] * 12
        idx, n = ds.choose(thin)
        self.assertEqual(n, 12)
        self.assertEqual(len(idx), ds.ORBITS)
        self.assertTrue(set(range(500, 512)) <= set(idx))  # every chaotic one, then the highest
        self.assertIn(499, idx)
        self.assertNotIn(0, idx)


class PlaceFit(unittest.TestCase):
    def walks(self, D, m, t, seed):
        rng = random.Random(seed)
        q = []
        for _ in range(m):
            x, prev, row = rng.gauss(0, 1e-6), 0.0, []
            for tk in t:
                x += rng.gauss(0, math.sqrt(2 * D * (tk - prev)))
                prev = tk
                row.append(x)
            q.append(row)
        return q

    def test_known_D(self):
        t = [100.0 * k for k in range(1, 42)]
        ranges = ds.ranges_of(t, 400.0)
        inside = 0
        for seed in range(20):
            D = 3e-9
            f = ds.place_fit(self.walks(D, 200, t, seed), t, ranges)
            d, se = f["full"]
            # the same D as a least-squares line through the variance
            a, b = ranges["full"]
            self.assertAlmostEqual(d, ds.line_fit(t[a:b + 1], f["var"][a:b + 1])[1] / 2, delta=1e-6 * d)
            self.assertLess(abs(d - D), 4 * se)
            self.assertTrue(0.03 < se / D < 0.3, se / D)
            inside += abs(d - D) < se
            self.assertLess(abs(math.log(f["second"][0] / f["first"][0])), math.log(2))
        # the jackknife error is honest: about 68 % of the estimates within one error (binomial 13.6 +- 2.1)
        self.assertTrue(9 <= inside <= 19, inside)

    def test_classify(self):
        row = {"D": 1e-15, "D_se": 1e-17, "D_first": 1.1e-15, "D_second": 0.9e-15}
        self.assertEqual(ds.classify(row)[0], "point")
        row.update(D_first=2e-15, D_second=0.5e-15)
        kind, lo, hi = ds.classify(row)
        self.assertEqual(kind, "interval")
        self.assertAlmostEqual(lo, math.log(0.5e-15))
        self.assertAlmostEqual(hi, math.log(2e-15))
        kind, lo, hi = ds.classify({"D": -1e-16, "D_se": 1e-16, "D_first": 0, "D_second": 0})
        self.assertEqual(kind, "upper")
        self.assertAlmostEqual(hi, math.log(3e-16))

    def test_truncated_moments(self):
        mu, tau, lo, hi = 0.3, 1.7, -0.5, 1.2
        n, s0, s1, s2 = 20000, 0.0, 0.0, 0.0
        for i in range(n):  # the density on [lo, hi] by the midpoint rule
            y = lo + (i + 0.5) * (hi - lo) / n
            w = ds.phi((y - mu) / tau) / tau * (hi - lo) / n
            s0, s1, s2 = s0 + w, s1 + w * y, s2 + w * y * y
        m, m2, lz = ds.truncated_moments(mu, tau, lo, hi)
        self.assertAlmostEqual(m, s1 / s0, places=6)
        self.assertAlmostEqual(m2, s2 / s0, places=6)
        self.assertAlmostEqual(lz, math.log(s0), places=6)


class Law(unittest.TestCase):
    GRID = [round(0.02 + 0.02 * i, 6) for i in range(75)]

    def test_known_exponent_recovered(self):
        for seed in (3, 5):
            res = ds.analyse(ds.load_results(synthetic(self, {"a": 0.25, "places": 32, "seed": seed})), self.GRID)
            self.assertTrue(res["i95"][0] <= 0.25 <= res["i95"][1], (seed, res["a"], res["i95"]))
            self.assertLess(res["sigma_a"], 0.1)
            self.assertFalse(res["edge"])
            self.assertGreater(res["lr_power"], 3.84)  # the power law is excluded
            self.assertAlmostEqual(res["par"]["tau"], 2.3, delta=0.3)
            kinds = sum(res["kinds"].values(), [])
            self.assertGreater(kinds.count("upper"), 0)  # censored runs were kept, not dropped
            self.assertEqual(res["n"], 12 * 32)

    def test_power_law_not_excluded(self):
        res = ds.analyse(ds.load_results(synthetic(self, {"power": 6.3, "lnD0": 2.0, "places": 32, "seed": 4})),
                         self.GRID)
        self.assertLess(res["lr_power"], 3.84)
        self.assertAlmostEqual(res["power"]["b1"], 6.3, delta=0.6)
        self.assertEqual(res["i95"][0], 0.02)  # the interval reaches the grid's smallest a

    def test_fit_report(self):
        import contextlib
        import io
        dirs = synthetic(self, {"a": 0.25, "places": 24, "seed": 8})
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            res = ds.cmd_fit({"grid": "0.05"}, dirs)
        text = out.getvalue()
        self.assertEqual(sum(1 for line in text.splitlines() if line.startswith("| 0.") and " | 24 | " in line), 12)
        self.assertIn(f"a = {res['a']:.3f}", text)
        self.assertIn("independent the power law is excluded" if res["lr_power"] > 3.84 else "not excluded", text)
        adj = res["correlated"]
        line = next(x for x in text.splitlines() if x.startswith("with the correlation"))
        self.assertIn(f"the places counted as ~{adj['places']:.0f}", line)
        self.assertIn("the power law is excluded" if adj["lr_power"] > 3.84 else "the power law is not excluded", line)

    def test_svg_draws_every_run_and_the_fitted_law(self):
        import xml.etree.ElementTree as ET
        dirs = synthetic(self, {"a": 0.25, "places": 16, "seed": 9})
        rows = ds.load_results(dirs)
        res = ds.analyse(rows, self.GRID)
        path = os.path.join(temp_dir(self), "d_eps.svg")
        ds.svg(rows, res, path)
        ns = "{http://www.w3.org/2000/svg}"
        root = ET.parse(path).getroot()  # well-formed
        kinds = [ds.classify(r)[0] for r in rows]
        self.assertEqual(len(root.findall(ns + "circle")), kinds.count("point"))
        legend = " ".join(t.text for t in root.findall(ns + "text"))
        above = int(legend.split("upper limits (")[1].split(" above")[0])
        self.assertEqual(len(root.findall(ns + "path")) + above, kinds.count("upper"))
        self.assertIn(f"a = {res['a']:g}", legend)
        law = [e for e in root.findall(ns + "line") if e.get("stroke") == "#c33"]
        self.assertEqual(len(law), 1)
        # the law's line falls from the largest eps (left) to the smallest (right), as fitted
        self.assertLess(float(law[0].get("y1")), float(law[0].get("y2")))

    def test_correlated_places_widen_the_interval(self):
        res = ds.analyse(ds.load_results(synthetic(self, {"a": 0.25, "places": 32, "seed": 3})), self.GRID)
        same = ds.correlated(res, float("nan"))
        self.assertEqual((same["i68"], same["lr_power"]), (res["i68"], res["lr_power"]))
        adj = ds.correlated(res, 0.437)  # what the ten-eps scan measured: ~50 of 128 places
        f = (1 - 0.437) / (1 + 0.437)
        self.assertAlmostEqual(adj["lr_power"], res["lr_power"] * f)
        self.assertLessEqual(adj["i68"][0], res["i68"][0])
        self.assertGreaterEqual(adj["i68"][1], res["i68"][1])
        self.assertGreater(adj["sigma_a"], res["sigma_a"])
        self.assertAlmostEqual(adj["places"], 32 * f)

    def test_step_check(self):
        main, step = temp_dir(self), temp_dir(self)
        for d, scale in ((main, 1.0), (step, 2.0)):
            with gzip.open(os.path.join(d, "curves.csv.gz"), "wt", newline="") as f:
                w = csv.writer(f)
                w.writerow(["place", "t", "var_along", "var_across", "mean_along"])
                rng = random.Random(7)
                for p in range(8):
                    D = 1e-17 * (1 + p)
                    for k in range(1, 31):
                        w.writerow([p, k * 3e5, 1e-11 + 2 * scale * D * k * 3e5 * (1 + 0.01 * rng.gauss(0, 1)), 0, 0])
        n, m, se = ds.step_check(main, step, 9e5, 9e6)
        self.assertEqual(n, 8)
        self.assertAlmostEqual(m, math.log(2), delta=3 * se + 0.01)

    def test_shift_moves_one_eps_by_its_amount(self):
        rows = [{"eps": e, "place": p, "D": d, "D_se": d / 10, "D_first": d, "D_second": d * k}
                for e in (0.001, 0.002) for p, (d, k) in enumerate(((1e-18, 1.1), (1e-18, 3.0), (1e-20, 1.0)))]
        rows[2]["D_se"] = 1e-19          # unresolved: an upper limit
        moved = ds.shifted(rows, 0.001, 0.27)
        for before, after in zip(rows, moved):
            (k0, lo0, hi0), (k1, lo1, hi1) = ds.classify(before), ds.classify(after)
            self.assertEqual(k0, k1)
            dx = 0.27 if before["eps"] == 0.001 else 0.0
            self.assertAlmostEqual(hi1 - hi0, dx, places=12)
            if lo0 != -math.inf:
                self.assertAlmostEqual(lo1 - lo0, dx, places=12)
        self.assertEqual(rows[0]["D"], 1e-18)            # the input is not changed
        with self.assertRaises(SystemExit):
            ds.shifted(rows, 0.003, 0.27)


class Design(unittest.TestCase):
    def test_present_design(self):
        csv_path = os.path.join(os.path.dirname(ds.__file__), "results", "2026-11-26-d-eps-places.csv")
        sv, su, m = ds.variance_components(csv_path)
        self.assertAlmostEqual(sv, 2.31, delta=0.01)
        # the estimate for the 16-place design: sigma(a) ~ 0.14
        s = ds.fisher_sigma_a(ds.logspace(0.0025, 0.02, 12), sv / 4, 0.25, 7.29)
        self.assertAlmostEqual(s, 0.14, delta=0.01)
        self.assertLess(ds.fisher_sigma_a(ds.logspace(0.0013, 0.02, 12), sv / math.sqrt(128), 0.25, 7.29), 0.05)


if __name__ == "__main__":
    unittest.main()
