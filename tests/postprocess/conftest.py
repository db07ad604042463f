"""Markers of the postprocess tests: `browser` tests drive Chromium (their own CTest entry,
postprocess_browser, which CTest reports as skipped where Chromium, node or playwright-core
is missing)."""


def pytest_configure(config):
    config.addinivalue_line("markers", "browser: drives Debian's chromium through playwright-core")
