"""Library models (TOML), shipped in the wheel as flake8_rosgraph.stubs; data only."""
