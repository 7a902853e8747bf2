"""Camera calibrators: one camera gives one CameraInfo, a stereo pair gives two."""
from sensor_msgs.msg import CameraInfo


class MonoCalibrator:
    is_mono = True

    def __init__(self, size):
        self.size = size

    def as_message(self):
        info = CameraInfo()
        info.width, info.height = self.size
        return info


class StereoCalibrator(MonoCalibrator):
    is_mono = False

    def as_message(self):
        return (MonoCalibrator.as_message(self), MonoCalibrator.as_message(self))
