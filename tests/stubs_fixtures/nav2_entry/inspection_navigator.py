"""A navigator subclass that only a launch file starts: nothing here instantiates it."""
from nav2_simple_commander.robot_navigator import BasicNavigator
from std_msgs.msg import String


class InspectionNavigator(BasicNavigator):
    def __init__(self):
        super().__init__('inspection_navigator', namespace='inspector')
        self.report_pub = self.create_publisher(String, 'inspection_report', 10)
