"""Names the monitor shares with the C++ base driver."""
ODOM = 'odom'
STATUS = 'driver_status'
RESET_SERVICE = '/base_driver/reset'
