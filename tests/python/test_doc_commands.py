"""The python commands of the docs (README.md, docs/*.md, the scenes' comments):
`python -c ...`, the python blocks, `pip install` of the wheel, the scripts that
draw with matplotlib, run at a CPU size with this environment's python, as
tests/docs/doc_commands.py runs the shell ones (ctest docs; docs/reliability.md,
"Documented commands")."""
import importlib.util
import os
import shutil
import sys

import pytest

from conftest import REPO, cli_path


def _load():
    spec = importlib.util.spec_from_file_location("doc_commands", REPO / "tests" / "docs" / "doc_commands.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["doc_commands"] = module  # (its dataclasses look their module up)
    spec.loader.exec_module(module)
    return module


dc = _load()
_CLI = os.environ.get("ARNOLDWEB_CLI")
_PRESENT = dc.devices_present(_CLI) if _CLI else {"cpu"}
_ERRORS: list[str] = []
_PLANS = [p for p in dc.all_plans(dc.load_rules(), False, _PRESENT, _ERRORS) if p.steps and p.element.is_python]


def test_the_docs_markers_read():
    assert not _ERRORS, "\n".join(_ERRORS)


def test_there_are_python_commands():
    assert len(_PLANS) >= 8


@pytest.mark.parametrize("plan", _PLANS, ids=[p.element.where for p in _PLANS])
def test_documented_python_command(plan):
    cli = _CLI or cli_path()
    build = os.path.dirname(os.path.abspath(_CLI)) if _CLI else str(REPO / "build")
    env, bindir = dc.environment(cli, sys.executable)
    try:
        ok, log, _ = dc.run_plan(plan, env, build, keep=False)
    finally:
        shutil.rmtree(bindir, ignore_errors=True)
    assert ok, log
