"""Shared set-up of the browser tests: find Chromium, Playwright and a CJK font, or skip.

With ``MECH_BROWSER_TEST=required`` (set by ``.ci/run``) or ``CI=true`` a missing piece
fails the test instead of skipping it, so CI cannot pass without running the browser.
"""

import os

import pytest

import _crawl


def browser_required():
    return (os.environ.get("MECH_BROWSER_TEST", "").lower() == "required"
            or os.environ.get("CI", "").lower() == "true")


def unavailable(reason):
    """Skip with ``reason``, or fail when the browser test is required."""
    if browser_required():
        pytest.fail(f"{reason} (the browser test is required here: MECH_BROWSER_TEST=required or CI=true)")
    pytest.skip(reason)


@pytest.fixture(scope="session")
def chromium():
    try:
        import playwright  # noqa: F401
    except ImportError:
        unavailable("Playwright is not installed (make setup installs it from requirements.txt)")
    path = _crawl.chromium_path()
    if path is None:
        unavailable("no Chromium on this machine (make browser-deps installs Debian's chromium)")
    if not _crawl.has_cjk_font():
        unavailable("no font with Chinese glyphs (make browser-deps installs fonts-noto-cjk)")
    return path
