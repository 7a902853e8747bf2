"""--rosgraph-interfaces / ROSGRAPH_INTERFACES / check --interfaces: interface packages outside
the workspace, and the cache key that follows their files."""
import os
import subprocess
import sys
import textwrap
from pathlib import Path

from flake8_rosgraph import cache
from flake8_rosgraph.options import Settings

NODE = textwrap.dedent("""\
    import rclpy
    from rclpy.node import Node
    from vendor_msgs.msg import Gripper


    class Hand(Node):
        def __init__(self):
            super().__init__('hand')
            self.create_timer(0.5, self.on_tick)

        def on_tick(self):
            grip = Gripper()
            grip.force = 3
            grip.width = 0.02
            return grip


    def main():
        rclpy.init()
        rclpy.spin(Hand())
    """)


def _layout(tmp_path: Path) -> tuple[Path, Path]:
    ws = tmp_path / "ws"
    pkg = ws / "src" / "hand"
    (pkg / "hand").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='3'><name>hand</name></package>")
    (pkg / "hand" / "__init__.py").write_text("")
    (pkg / "hand" / "node.py").write_text(NODE)
    vendor = tmp_path / "vendor" / "vendor_msgs"
    (vendor / "msg").mkdir(parents=True)
    (vendor / "package.xml").write_text("<package format='3'><name>vendor_msgs</name></package>")
    (vendor / "msg" / "Gripper.msg").write_text("float64 force\nfloat64 width\n")
    return ws, tmp_path / "vendor"


def _check(args: list[str], cwd: Path, env_extra: dict | None = None) -> str:
    env = {key: value for key, value in os.environ.items() if key != "ROSGRAPH_INTERFACES"}
    env.update(env_extra or {})
    done = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "check", "--select", "ROS107",
                           *args, "."], cwd=cwd, capture_output=True, text=True, env=env, timeout=300)
    return done.stdout


def test_messages_of_a_vendor_folder_are_checked_only_when_given(tmp_path):
    ws, vendor = _layout(tmp_path)
    cache_dir = ["--cache-dir", str(tmp_path / "cache")]
    assert _check(cache_dir, ws) == ""
    flagged = _check(cache_dir + ["--interfaces", str(vendor)], ws)
    assert "src/hand/hand/node.py:13:9: ROS107 vendor_msgs/msg/Gripper field 'force' (float64) " \
           "rejects the int 3" in flagged
    assert _check(cache_dir, ws, {"ROSGRAPH_INTERFACES": str(vendor)}) == flagged


def test_settings_and_cache_key_follow_the_interface_folders(tmp_path):
    ws, vendor = _layout(tmp_path)
    settings = Settings.resolve({}, {"ROSGRAPH_INTERFACES": f"{vendor}, {tmp_path / 'more'}"})
    assert settings.interface_dirs == (vendor, tmp_path / "more")
    before = cache.cache_key(ws, settings)
    (vendor / "vendor_msgs" / "msg" / "Gripper.msg").write_text("int32 force\nfloat64 width\n")
    assert cache.cache_key(ws, settings) != before
    own = cache.cache_key(ws, Settings())
    (ws / "src" / "hand" / "msg").mkdir()
    (ws / "src" / "hand" / "msg" / "Local.msg").write_text("int8 x\n")
    assert cache.cache_key(ws, Settings()) != own
