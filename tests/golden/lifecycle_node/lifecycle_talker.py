"""A lifecycle node whose publisher and timer appear in on_configure."""
import rclpy
import rclpy.lifecycle
from rclpy.lifecycle import TransitionCallbackReturn
from std_msgs.msg import String


class LifecycleTalker(rclpy.lifecycle.Node):

    def __init__(self):
        super().__init__('lc_talker')
        self._pub = None
        self._timer = None
        self.count = 0

    def on_configure(self, state):
        self._pub = self.create_lifecycle_publisher(
            String, 'lifecycle_chatter', 10)
        self._timer = self.create_timer(1.0, self.publish)
        return TransitionCallbackReturn.SUCCESS

    def on_cleanup(self, state):
        self.destroy_timer(self._timer)
        self.destroy_lifecycle_publisher(self._pub)
        return TransitionCallbackReturn.SUCCESS

    def publish(self):
        self.count += 1
        self._pub.publish(String(data='lifecycle %d' % self.count))


def main(args=None):
    rclpy.init(args=args)
    node = LifecycleTalker()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
