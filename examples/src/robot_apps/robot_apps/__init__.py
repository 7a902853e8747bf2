"""Applications of the example robot: teleop, dashboard, Fibonacci actions."""
