"""The command message types the ``command_type`` parameter selects."""
from geometry_msgs.msg import Twist, TwistStamped

COMMAND_TYPES = {'twist': Twist, 'stamped': TwistStamped}
