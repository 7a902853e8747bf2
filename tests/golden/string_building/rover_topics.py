"""Topic names built with f-strings, concatenation, % and str.format."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class RoverTopics(Node):

    def __init__(self):
        super().__init__('rover_topics')
        robot = 'rover'
        index = 2
        self.create_publisher(String, f'{robot}/status', 10)
        self.create_publisher(String, f'/{robot}/wheel_{index}/speed', 10)
        self.create_publisher(String, robot + '/odom_text', 10)
        self.create_publisher(String, 'joint_' + str(index), 10)
        self.create_publisher(String, '%s/camera%d' % (robot, index), 10)
        self.create_publisher(String, '/%s/log' % robot, 10)
        self.create_publisher(String, '{}/arm_{}'.format(robot, index), 10)
        self.create_publisher(String, '{name}/gripper'.format(name=robot), 10)


def main(args=None):
    rclpy.init(args=args)
    node = RoverTopics()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
