"""Installs the fake analysis in every Python process that has this directory on PYTHONPATH."""
import rosgraph_fakes

rosgraph_fakes.install()
