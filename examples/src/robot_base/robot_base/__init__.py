"""Building blocks shared by the robot packages of the example workspace."""
