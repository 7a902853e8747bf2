"""Drivers of the example robot, built on robot_base."""
