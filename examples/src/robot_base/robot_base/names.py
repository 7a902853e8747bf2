"""Topic and service names shared by the robot packages.

Publishers and subscribers import the same constant, so a rename cannot leave
one end behind; the linter follows these imports to resolve each name.
Relative names are expanded against the namespace of the node that uses them.
"""

ROBOT_NAMESPACE = 'robot1'

HEARTBEAT_TOPIC = '/heartbeat'
SCAN_TOPIC = 'scan'
CMD_VEL_TOPIC = 'cmd_vel'
ODOM_TOPIC = 'odom'

ENABLE_MOTORS_SERVICE = 'enable_motors'
