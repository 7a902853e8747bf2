"""The system as it runs: packages, executables, launch files, remapping and parameters.

The entry points live in :mod:`.api` (kept out of this file so that importing a
launch data class — as the rules do — does not load the analyser).
"""
