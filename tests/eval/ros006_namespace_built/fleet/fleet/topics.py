"""Per-robot topic names: every robot's nodes live under the robot's namespace."""


def robot_topic(node, name):
    return node.get_namespace() + '/' + name
