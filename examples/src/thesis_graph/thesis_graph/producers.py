"""node_1 and node_2 of the thesis graph: the nodes that publish most topics.

node_1 both subscribes to and publishes ``topic1``, and node_2 both publishes
and subscribes to ``topic7``: the two self-loops (red edges) of the thesis's
figure 6.4. node_2 is also the only publisher of ``topic5``, which nobody
subscribes to.
"""
from rclpy.node import Node
from std_msgs.msg import String


class ROSNode1(Node):
    """Listens on topic1 and topic3, publishes topic7 and topic1."""

    def __init__(self):
        super().__init__('node_1')
        self.create_subscription(  # ROS002: node_1 publishes topic1 too
            String,
            'topic1',
            self.listener_callback,
            10)
        self.create_publisher(
            String,
            'topic7',
            10)
        self.create_publisher(
            String,
            'topic1',
            10)
        self.create_subscription(
            String,
            'topic3',
            self.listener_callback,
            10)

    def listener_callback(self, msg):
        self.get_logger().info('I heard: "%s"' % msg.data)


class ROSNode2(Node):
    """Publishes topic1 to topic7 and listens to its own topic7."""

    def __init__(self):
        super().__init__('node_2')
        self.publisher = self.create_publisher(String, 'topic1', 10)
        self.create_publisher(String, 'topic2', 10)
        self.create_publisher(String, 'topic3', 10)
        self.create_publisher(String, 'topic4', 10)
        self.create_publisher(String, 'topic5', 10)  # ROS001: no subscriber
        self.create_publisher(String, 'topic6', 10)
        self.create_publisher(String, 'topic7', 10)
        self.create_subscription(  # ROS002: node_2 publishes topic7 too
            String, 'topic7', self.topic7_callback, 10)
        timer_period = 0.5  # seconds
        self.timer = self.create_timer(timer_period, self.timer_callback)
        self.i = 0

    def topic7_callback(self, msg):
        self.get_logger().info('I heard: "%s"' % msg.data)

    def timer_callback(self):
        msg = String()
        msg.data = 'Hello World: %d' % self.i
        self.publisher.publish(msg)
        self.get_logger().info('Publishing: "%s"' % msg.data)
        self.i += 1
