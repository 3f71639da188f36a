#!/usr/bin/env python3
"""bench/ab_pairs.py, the whole-process A/B timer the docs' timing commands are written for: the
pairs it runs, the lower bounds a sleeping command sets, its exit codes (2 bad arguments, 3 the time
bound), and a command's own exit code reported, not acted on. No timing is asserted beyond what
`sleep` guarantees."""
import os
import subprocess
import sys
import unittest

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench", "ab_pairs.py")


def ab(*args):
    p = subprocess.run([sys.executable, TOOL, *args], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def medians(text):
    """{'A wall s': median, ...} from the report."""
    out = {}
    for line in text.splitlines():
        parts = line.rsplit(None, 3)
        if len(parts) == 4:
            try:
                out[parts[0]] = float(parts[2])
            except ValueError:
                pass
    return out


class AbPairs(unittest.TestCase):
    def test_pairs_and_sleep_bounds(self):
        rc, out, _ = ab("-n", "2", "--warmup", "0", "--vs", "sleep 0.05", "--", "sleep", "0.2")
        self.assertEqual(rc, 0, out)
        self.assertTrue(out.startswith("2 pairs after 0 warm-up"), out)
        m = medians(out)
        self.assertGreaterEqual(m["A wall s"], 0.2)
        self.assertGreaterEqual(m["B wall s"], 0.05)
        self.assertGreater(m["A/B wall"], 1.0)  # 0.2 s of sleep against 0.05 s plus the same start-up

    def test_single_command_and_its_exit_code(self):
        rc, out, _ = ab("-n", "2", "--warmup", "0", "--", "false")
        self.assertEqual(rc, 0, out)
        self.assertIn("2 runs after 0 warm-up", out)
        self.assertIn("A exit codes [1]", out)
        self.assertNotIn("A/B", out)

    def test_time_bound(self):
        rc, out, _ = ab("-n", "5", "--warmup", "0", "--timeout", "0.5", "--", "sleep", "0.3")
        self.assertEqual(rc, 3, out)
        self.assertIn("the time bound ended the call early", out)

    def test_bad_arguments(self):
        for args in (["-x", "1", "--", "true"], ["-n", "two", "--", "true"], ["-n", "2"], ["-n", "0", "--", "true"]):
            rc, _, err = ab(*args)
            self.assertEqual(rc, 2, args)
            self.assertIn("ab_pairs.py:", err)


if __name__ == "__main__":
    unittest.main()
