"""docs/python.md: its API reference is the docstrings' (regenerate with
`python -m arnoldweb._apidoc docs/python.md`), and its example runs."""
import re

from arnoldweb import _apidoc


def test_api_reference_is_current(repo):
    page = (repo / "docs" / "python.md").read_text(encoding="utf-8")
    assert _apidoc.replace(page) == page, \
        "docs/python.md is stale: run `python -m arnoldweb._apidoc docs/python.md` with the package installed"


def test_every_public_name_is_documented():
    import arnoldweb as aw
    for name in aw.__all__:
        obj = getattr(aw, name)
        if callable(obj):
            assert (obj.__doc__ or "").strip(), name


def test_readme_and_page_start_with_the_wheel(repo):
    wheel = r"^pip install --find-links \S+ arnoldweb\b"  # the wheelhouse: pip picks the Python's wheel
    readme = (repo / "README.md").read_text(encoding="utf-8")
    assert re.search(wheel, readme, re.M)
    page = (repo / "docs" / "python.md").read_text(encoding="utf-8")
    install = page.index("## Install")
    assert re.search(wheel, page[install:], re.M) and page.index("pip install --find-links") < page.index("## The Figure")
