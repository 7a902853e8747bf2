"""Per-type summaries: each is written for one message type and reached only for it."""


def image_summary(msg):
    return {'encoding': msg.encoding, 'shape': [msg.height, msg.width], 'step': msg.step}


def cloud_summary(cloud):
    assert cloud.point_step * cloud.width * cloud.height == len(cloud.data)
    return {'fields': [field.name for field in cloud.fields]}


def scan_summary(msg):
    return {'ranges': [round(r, 3) for r in msg.ranges],
            'max': msg.range_maximum}  # ROS107


def grid_summary(msg):
    return {'resolution': msg.info.resolution, 'size': [msg.info.width, msg.info.height]}
