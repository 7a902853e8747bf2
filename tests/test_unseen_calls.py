"""Names a node hands, with itself, to a library the analysis cannot see (graph/unseen_calls.py)."""
import ast

from flake8_rosgraph.graph.unseen_calls import HELD, helpers_handed, names_handed_to_unseen_code

SOURCE = '''
import gated_io
import rclpy
from gated_io.filters import OnOffFilterState as Gate
from vision.head import HeadControl


class Detector(rclpy.node.Node):
    def __init__(self):
        super().__init__('detector')
        self.a = gated_io.OnOffSubscriber(self, Image, 'image_raw', self.cb, 1)
        self.b = Gate(self, state_service_name='pose/filter_state')
        self.c = gated_io.format('not/handed', 3)
        self.d = known.Thing(self, 'known/name')
        self.e = HeadControl(self, 'head')
'''


def _names(source: str, receiver: str = "self") -> tuple[str, ...]:
    tree = ast.parse(source)
    return names_handed_to_unseen_code(tree, tree, lambda callee: callee.startswith("vision."), receiver)


def test_only_strings_handed_with_the_node_to_unseen_imports_count():
    assert _names(SOURCE) == ("image_raw", "pose/filter_state")


def test_a_modelled_or_workspace_callee_hands_nothing_over():
    tree = ast.parse(SOURCE)
    assert names_handed_to_unseen_code(tree, tree, lambda callee: True) == ()


def test_helper_classes_handed_the_node_are_candidates():
    assert helpers_handed(ast.parse(SOURCE)) == ("Gate", "HeadControl", "OnOffSubscriber", "Thing")


def test_a_helper_hands_over_the_node_it_holds():
    helper = '''
import gated_io


class HeadControl:
    def __init__(self, node, prefix):
        self.node = node
        self.gate = gated_io.OnOffFilterState(self.node, 'pose/filter_state')
        self.other = gated_io.Log('not a node')
'''
    assert _names(helper, HELD) == ("pose/filter_state",)
