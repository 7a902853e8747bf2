"""Helpers for tests that drive the headless browser (the ``browser`` fixture is in conftest)."""
from __future__ import annotations

from pathlib import Path


def open_page(driver: object, page: Path) -> None:
    """Load ``page`` and drain the console log, so a test sees only what its page logged."""
    driver.get_log("browser")  # type: ignore[attr-defined]
    driver.get(page.resolve().as_uri())  # type: ignore[attr-defined]


def console_errors(driver: object) -> list[str]:
    return [entry["message"] for entry in driver.get_log("browser")  # type: ignore[attr-defined]
            if entry["level"] == "SEVERE"]
