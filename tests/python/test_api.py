"""The package's API: catalogue, scenes, plans."""
import arnoldweb as aw
import pytest


def test_devices_lists_cpu_first():
    devs = aw.devices()
    assert devs[0]["id"] == "cpu"
    assert {"id", "backend", "name", "vendor", "fp64", "compute_units", "memory"} <= set(devs[0])
    assert all(isinstance(d["memory"], int) for d in devs)
    assert aw.default_device() in [d["id"] for d in devs]
    assert isinstance(aw.backend_problems(), list)


def test_methods_are_the_library_tables():
    ms = {m["name"]: m for m in aw.methods()}
    assert ms["leapfrog"]["order"] == 2
    assert ms["yoshida6a"]["order"] == 6
    assert ms["yoshida6a"]["stages"] == len(ms["yoshida6a"]["kick"]) - 1
    assert abs(sum(ms["yoshida6a"]["drift"]) - 1.0) < 1e-14
    assert ms["yoshida6a"]["gradient"] == [] and ms["yoshida6a"]["work"] == 7
    assert ms["chin4a"]["gradient"][1] == 1.0 / 72 and ms["chin4a"]["work"] > ms["chin4a"]["stages"]


def test_scene_keys_cover_every_section():
    keys = {k["key"] for k in aw.scene_keys()}
    assert {"model.energy", "ensemble.trajectories", "integrator.step", "output.dir"} <= keys


def test_from_file_set_chain_and_values(repo):
    base = aw.Scene.from_file(repo / "scenes" / "default.toml")
    s = base.set("model.energy", 30).set("ensemble.trajectories", 20000)
    assert s is not base and base["model.energy"] == 15.0 and base.overrides == []  # set() leaves base alone
    assert s["model.energy"] == 30.0
    assert s["ensemble.trajectories"] == 20000
    assert s.overrides == ["model.energy=30", "ensemble.trajectories=20000"]
    assert s.file.endswith("scenes/default.toml")
    assert "energy = 30" in s.to_toml()


def test_set_spells_python_values_as_toml(small_scene):
    s = small_scene
    s = s.set("observe.velocity_map", {"nside": 8}).set("integrator.method", "leapfrog")
    s = s.set("observe.initial_states", True).set("ensemble.cap.center", (10.0, -5))
    assert s["observe.velocity_map.nside"] == 8
    assert s["integrator.method"] == "leapfrog"
    assert s["ensemble.cap.center"] == [10.0, -5.0]


def test_copy_is_independent(small_scene):
    c = small_scene.copy().set("model.energy", 40)
    assert c["model.energy"] == 40.0
    assert small_scene["model.energy"] == 15.0


def test_from_toml_and_from_dict_agree(small_scene):
    t = aw.Scene.from_toml(small_scene.to_toml())
    assert t.to_dict() == small_scene.to_dict()
    dotted = aw.Scene.from_dict({"model.energy": 15.0, "ensemble.trajectories": 3000, "ensemble.seed": 7,
                                 "integrator": {"method": "yoshida6a", "step": 0.02},
                                 "run": {"average": 5.0, "duration": 5.0, "device": "cpu"},
                                 "observe": {"velocity_map": {"nside": 16}, "energy_error": {"every": 1.0}},
                                 "output.images": False})
    assert dotted.to_dict() == small_scene.to_dict()


def test_from_dict_panels_give_panel_tables(small_scene):
    d = small_scene.to_dict()
    s = aw.Scene.from_dict({"model": {"energy": 15.0}, "run": {"device": "cpu"},
                            "panel": [{"name": "b", "title": "zoom", "set": ["ensemble.trajectories=100"]}]})
    plan = s.check()
    assert [p["name"] for p in plan["panels"]] == ["b"]
    assert plan["panels"][0]["trajectories"] == 100
    assert d["model"]["energy"] == 15.0


def test_check_returns_the_plan(small_scene):
    p = small_scene.check()
    assert p["method"] == "yoshida6a"
    assert p["steps_per_trajectory"] == 250  # 5 T at 0.02 T
    assert p["windows"] == 1
    assert p["trajectory_steps"] == 3000 * 250
    assert p["nside"] == 16 and p["npix"] == 12 * 16 * 16
    assert "velocity_map" in p["effects"] and "energy_error" in p["effects"]
    assert 0 < p["step_guard"]["value"] < p["step_guard"]["limit"]
    assert p["memory"]["device_bytes"] > 0
    assert p["scene"]["ensemble"]["trajectories"] == 3000
    assert p["panels"] == []


def test_scene_cannot_be_built_directly():
    with pytest.raises(TypeError):
        aw.Scene()


def test_unsupported_value_type(small_scene):
    with pytest.raises(TypeError):
        small_scene.set("model.energy", object())


def test_the_package_cli_is_installed():
    from arnoldweb import _cli
    import subprocess
    out = subprocess.run([_cli.executable(), "methods"], capture_output=True, text=True)
    assert out.returncode == 0 and "yoshida6a" in out.stdout


def test_type_stubs_are_installed():
    import pathlib
    pkg = pathlib.Path(aw.__file__).parent
    stub = (pkg / "_arnoldweb.pyi").read_text()
    assert "def devices() -> list" in stub and "class _Run" in stub
    assert (pkg / "py.typed").exists()
