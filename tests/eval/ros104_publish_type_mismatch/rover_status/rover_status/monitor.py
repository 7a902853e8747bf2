import rclpy
from geometry_msgs.msg import Twist, TwistStamped
from std_msgs.msg import Int32
from std_srvs.srv import SetBool, Trigger

from rover_status.base import RoverNode
from rover_status.messages import level_message, mode_message


class Monitor(RoverNode):

    def __init__(self):
        super().__init__('monitor')
        self.stamped = self.declare_parameter('stamped', False).value
        if self.stamped:
            self.cmd_pub = self.create_publisher(TwistStamped, 'cmd_vel', 10)
        else:
            self.cmd_pub = self.create_publisher(Twist, 'cmd_vel', 10)
        self.create_timer(1.0, self.on_tick)
        self.create_subscription(Int32, 'level_in', self.on_level, 10)
        self.create_service(SetBool, 'enable', self.on_enable)
        self.create_service(Trigger, 'reset', self.on_reset)
        self.create_service(SetBool, 'pause', self.on_pause)

    def on_tick(self):
        self.level_pub.publish(mode_message('docked'))  # ROS104
        self.mode_pub.publish(mode_message('auto'))
        self.level_pub.publish(level_message(80))
        self.mode_pub.publish('auto')  # ROS104
        # The publisher and the message follow the same flag: never mixed at run time.
        if self.stamped:
            cmd = TwistStamped()
        else:
            cmd = Twist()
        self.cmd_pub.publish(cmd)

    def on_level(self, msg):
        # What a subscription receives is not known statically: never judged.
        self.level_pub.publish(msg)

    def on_enable(self, request, response):  # ROS104
        result = Trigger.Response()
        result.success = True
        return result

    def on_reset(self, request, response):
        response.success = True
        return response

    def on_pause(self, request, response):
        return SetBool.Response(success=request.data)



def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Monitor())
