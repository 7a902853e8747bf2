"""docs/rules.md is generated from the rule docstrings and must stay in sync with them."""
from pathlib import Path

from flake8_rosgraph.rules import RULES
from flake8_rosgraph.rules.docs import main, render, rule_doc

DOCS = Path(__file__).resolve().parents[2] / "docs" / "rules.md"


def test_docs_rules_md_is_up_to_date():
    assert DOCS.read_text(encoding="utf-8") == render(RULES), (
        "docs/rules.md is stale: run `python -m flake8_rosgraph.rules.docs docs/rules.md`")


def test_page_has_every_rule_and_its_sections():
    page = render(RULES)
    for rule in RULES:
        assert f"## {rule.code} {rule.name}" in page
        assert rule_doc(rule).section("Why is this bad?") in page


def test_command_writes_then_checks(tmp_path, capsys):
    out = tmp_path / "docs" / "rules.md"
    assert main(["--check", str(out)]) == 1
    assert "out of date" in capsys.readouterr().err
    assert main([str(out)]) == 0
    assert main(["--check", str(out)]) == 0
    out.write_text(out.read_text() + "edited\n")
    assert main(["--check", str(out)]) == 1
