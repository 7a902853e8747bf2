"""Turns any message into a JSON-ready dict, choosing a summary by the message class."""
from web_bridge import summaries


def to_dict(msg):
    if msg.__module__ == 'sensor_msgs.msg._image':
        return summaries.image_summary(msg)
    if msg.__module__ in ('sensor_msgs.msg._point_cloud2', 'sensor_msgs.msg._PointCloud2'):
        return summaries.cloud_summary(msg)
    if type(msg).__name__ == 'LaserScan':
        return summaries.scan_summary(msg)
    if msg.__class__.__name__ == 'OccupancyGrid':
        return summaries.grid_summary(msg)
    return {'type': type(msg).__name__}
