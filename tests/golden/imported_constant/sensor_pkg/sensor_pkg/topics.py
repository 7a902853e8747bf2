"""Topic names shared by the nodes of this package."""

IMU_TOPIC = 'imu/data'
TEMPERATURE_TOPIC = '/temperature'
