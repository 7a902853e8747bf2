"""node_3 and node_4 of the thesis graph: the nodes that mostly listen.

node_3 subscribes to ``topic8``, which no node publishes (an orange topic in
the thesis's figure 6.4).
"""
from rclpy.node import Node
from std_msgs.msg import String


class ROSNode3(Node):
    """Listens to topics 2, 3, 6, 7, 4 and 8; counts with a timer."""

    def __init__(self):
        super().__init__('node_3')
        self.create_subscription(String, 'topic2', self.topic2_callback, 10)
        self.create_subscription(String, 'topic3', self.topic3_callback, 10)
        self.create_subscription(String, 'topic6', self.topic6_callback, 10)
        self.create_subscription(String, 'topic7', self.topic7_callback, 10)
        self.create_subscription(String, 'topic4', self.topic4_callback, 10)
        self.create_subscription(  # ROS003: no publisher
            String, 'topic8', self.topic8_callback, 10)
        timer_period = 0.5  # seconds
        self.timer = self.create_timer(timer_period, self.timer_callback)
        self.i = 0

    def topic2_callback(self, msg):
        self.get_logger().info('I heard on topic2: "%s"' % msg.data)

    def topic3_callback(self, msg):
        self.get_logger().info('I heard on topic3: "%s"' % msg.data)

    def topic4_callback(self, msg):
        self.get_logger().info('I heard on topic4: "%s"' % msg.data)

    def topic6_callback(self, msg):
        self.get_logger().info('I heard on topic6: "%s"' % msg.data)

    def topic7_callback(self, msg):
        self.get_logger().info('I heard on topic7: "%s"' % msg.data)

    def topic8_callback(self, msg):
        self.get_logger().info('I heard on topic8: "%s"' % msg.data)

    def timer_callback(self):
        self.get_logger().info('node_3 tick %d' % self.i)
        self.i += 1


class ROSNode4(Node):
    """Publishes topic1 and topic3, listens to topic2."""

    def __init__(self):
        super().__init__('node_4')
        self.create_publisher(String, 'topic1', 10)
        self.publisher = self.create_publisher(String, 'topic3', 10)
        self.create_subscription(String, 'topic2', self.topic2_callback, 10)
        timer_period = 0.5  # seconds
        self.timer = self.create_timer(timer_period, self.timer_callback)
        self.i = 0

    def topic2_callback(self, msg):
        self.get_logger().info('I heard: "%s"' % msg.data)

    def timer_callback(self):
        msg = String()
        msg.data = 'Hello World: %d' % self.i
        self.publisher.publish(msg)
        self.get_logger().info('Publishing: "%s"' % msg.data)
        self.i += 1
