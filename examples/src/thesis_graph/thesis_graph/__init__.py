"""The four-node / eight-topic ROS graph of the LiSA thesis (Code 6.7)."""
