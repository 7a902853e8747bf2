"""Topic names a launch file may override."""


def topic_or_default(node, parameter, default):
    """The topic a launch file gives as ``parameter``, else ``default``."""
    if node.has_parameter(parameter):
        return node.get_parameter(parameter).value
    return default
