"""The eval cases are workspaces to analyse, never tests to run: their ``test_*.py`` fixtures model a
package's own pytest files (test fixtures are their own system for the wiring rules)."""
collect_ignore_glob = ["*"]
