"""The C++ front end: rclcpp nodes of the workspace as partner ends for the Python rules.

Most ROS 2 workspaces mix rclcpp and rclpy; a Python subscription to a topic a
C++ node publishes is not dangling. This package reads the workspace's C++
sources with tree-sitter's C++ grammar (never regexes, never a compiler) and
adds what they create to the graph as :class:`~flake8_rosgraph.graph.model.RosNode`
objects with ``language="cpp"``:

* :mod:`.sources` finds the C++ files of the ROS packages and reads them within limits;
* :mod:`.syntax` parses them (tree-sitter) and reports damaged regions;
* :mod:`.values` evaluates the strings a name is built from (literals, constants of
  the same file, ``declare_parameter`` defaults);
* :mod:`.calls` knows the shapes of rclcpp calls (which call creates what, through which node);
* :mod:`.extract` finds the rclcpp calls, node classes and node creations of one file
  (records in :mod:`.facts`);
* :mod:`.to_graph` joins the files' facts into nodes and entities, names expanded by rcl
  rules (:mod:`flake8_rosgraph.graph.names`);
* :mod:`.reporting` keeps findings at the Python end: C++ ends are partners only.

The package is light to import; tree-sitter is only loaded when C++ sources exist.
"""

#: The suffixes read as C++ (sources and headers); here, so that the cache key can use them cheaply.
CPP_SUFFIXES = frozenset({".cpp", ".cc", ".cxx", ".hpp", ".hh", ".hxx", ".h"})
