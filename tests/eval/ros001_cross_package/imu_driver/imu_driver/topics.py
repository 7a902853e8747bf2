"""Topic names the driver shares with its consumers."""
DATA_TOPIC = 'imu/data'
