"""Tiny files must not make the analysis allocate huge amounts of memory.

Constant folding runs Python's own string operations on abstract constants, so
an innocent-looking ``'{:>400000000}'.format('a')`` would build a 400 MB string
before any size check saw the result. Each case here is one short line; the
analysis of it must stay below :data:`PEAK_LIMIT_KIB` of peak resident memory
(measured by the child itself; the address-space cap of the harness keeps a
regression from taking the machine down). This is a bound on memory, not a
claim about speed.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from .harness import assert_clean_exit, entity_keys, run
from .hostile_inputs import GOOD_ENTITIES, GOOD_FILES, write_files

#: Characters a hostile expression asks for: big enough to stand out from any honest analysis.
WIDTH = 400_000_000
#: Peak resident memory allowed for analysing the small workspace (an honest run needs a few tens of MiB).
PEAK_LIMIT_KIB = 256 * 1024

BOMBS = {
    "format_width": f"x = '{{:>{WIDTH}}}'.format('a')",
    "fstring_width": f"x = f'{{1:>{WIDTH}}}'",
    "format_builtin": f"x = format(1, '>{WIDTH}')",
    "percent_width": f"x = '%{WIDTH}s' % 'a'",
    "center": f"x = 'a'.center({WIDTH})",
    "ljust": f"x = 'a'.ljust({WIDTH})",
    "rjust": f"x = 'a'.rjust({WIDTH})",
    "zfill": f"x = 'a'.zfill({WIDTH})",
    "repeat": f"x = 'ab' * {WIDTH}",
    "repeat_list": f"x = [0] * {WIDTH}",
    "power": "x = 10 ** 10 ** 8",
    "shift": f"x = 1 << {WIDTH}",
    "replace_growth": "x = ('a' * 4000).replace('a', 'b' * 4000)",
    "join_growth": "x = ('a' * 4000).join(['b' * 4000] * 12)",
    "expandtabs": f"x = '\\t'.expandtabs({WIDTH})",
}

PEAK_PROBE = """
import resource, sys
from pathlib import Path
from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.graph.json_out import to_json
graph = build_graph(Path(sys.argv[1]))
sys.stdout.write(to_json(graph))
# VmHWM is this process's own peak: ru_maxrss would also count the parent's peak before exec
peak = [line for line in open("/proc/self/status") if line.startswith("VmHWM:")]
sys.stderr.write("peak-kib=%d\\n" % (int(peak[0].split()[1]) if peak else resource.getrusage(resource.RUSAGE_SELF).ru_maxrss))
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="ru_maxrss is in KiB on Linux only")
@pytest.mark.parametrize("name", sorted(BOMBS))
def test_small_file_small_memory(name: str, tmp_path: Path) -> None:
    root = tmp_path / "ws"
    write_files(root, {**{k: v.encode() for k, v in GOOD_FILES.items()},
                       "bomb.py": f"import rclpy\n{BOMBS[name]}\nrclpy.create_node('after_' + str(len(x)))\n".encode()})
    done = run([sys.executable, "-c", PEAK_PROBE, str(root)], tmp_path)
    assert_clean_exit(done)
    peak = int(done.stderr.rsplit("peak-kib=", 1)[1].split()[0])
    assert peak < PEAK_LIMIT_KIB, f"{name}: peak memory {peak // 1024} MiB for a one-line file"
    assert GOOD_ENTITIES <= entity_keys(json.loads(done.stdout))


#: A field rebuilt from its own value by a library call the stubs describe field by field (a
#: record): each re-run of the callback nests the last value once more, and its text doubles.
GROWING_RECORD = """
import os

import rclpy
from rclpy.node import Node


class Recorder(Node):
    def __init__(self):
        super().__init__('recorder')
        self.base_dir = 'recordings'
        self.base_dir = os.path.join(os.getcwd(), self.base_dir)
        self.session_dir = None
        self.create_timer(1.0, self.on_tick)

    def on_tick(self):
        self.base_dir = os.path.join(self.base_dir, 'next')
        self.session_dir = os.path.join(self.base_dir, self.session_dir or 'first')
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="ru_maxrss is in KiB on Linux only")
def test_a_field_rebuilt_from_itself_by_a_modelled_call_stays_small(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    write_files(root, {**{k: v.encode() for k, v in GOOD_FILES.items()}, "recorder.py": GROWING_RECORD.encode()})
    done = run([sys.executable, "-c", PEAK_PROBE, str(root)], tmp_path)
    assert_clean_exit(done)
    peak = int(done.stderr.rsplit("peak-kib=", 1)[1].split()[0])
    assert peak < PEAK_LIMIT_KIB, f"peak memory {peak // 1024} MiB for a 20-line node"
    graph = json.loads(done.stdout)
    assert GOOD_ENTITIES <= entity_keys(graph)
    assert "/recorder" in {node["fqn"] for node in graph["nodes"]}
