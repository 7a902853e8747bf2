"""scripts/generate_interfaces.py on a small hand-written tree of fake repositories."""
import importlib.util
import json
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "generate_interfaces.py"


@pytest.fixture(scope="module")
def script():
    spec = importlib.util.spec_from_file_location("generate_interfaces", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _tree(root: Path) -> None:
    base = root / "fake_common" / "alpha_msgs"
    (base / "msg").mkdir(parents=True)
    (base / "package.xml").write_text("<package><name>alpha_msgs</name></package>")
    (base / "msg" / "Reading.msg").write_text(
        "# A reading.\nHeader header\nfloat32 value 1.5  # default\nuint8 KIND_RAW=0\nValue[<=2] extra\n")
    (base / "msg" / "Value.msg").write_text("int64 v\n")
    unwanted = root / "fake_common" / "beta_msgs"
    (unwanted / "srv").mkdir(parents=True)
    (unwanted / "package.xml").write_text("<package><name>beta_msgs</name></package>")
    (unwanted / "srv" / "Ping.srv").write_text("---\nbool ok\n")
    (root / "fake_common.commit").write_text("0123abcd\n")


def test_generates_facts_with_their_source(script, tmp_path):
    _tree(tmp_path)
    document = script.generate(tmp_path, {"example/fake_common": ("alpha_msgs",)})
    assert document["sources"] == [{"repository": "github:example/fake_common", "commit": "0123abcd",
                                    "packages": ["alpha_msgs"]}]
    assert document["messages"] == {
        "alpha_msgs/msg/Reading": ["std_msgs/Header header", "float32 value",
                                   "alpha_msgs/Value[<=2] extra", "constant KIND_RAW"],
        "alpha_msgs/msg/Value": ["int64 v"],
    }


def test_main_writes_json_the_package_reads(script, tmp_path, monkeypatch):
    _tree(tmp_path)
    monkeypatch.setattr(script, "PACKAGES", {"example/fake_common": ("alpha_msgs", "beta_msgs")})
    out = tmp_path / "out.json"
    assert script.main([str(tmp_path), "-o", str(out)]) == 0
    data = json.loads(out.read_text())
    assert "beta_msgs/srv/Ping_Response" in data["messages"]


def test_missing_package_or_checkout_fails_loudly(script, tmp_path):
    _tree(tmp_path)
    with pytest.raises(SystemExit, match="packages not found: gamma_msgs"):
        script.generate(tmp_path, {"example/fake_common": ("gamma_msgs",)})
    with pytest.raises(SystemExit, match="missing checkout"):
        script.generate(tmp_path, {"example/absent": ("alpha_msgs",)})


def test_shipped_data_records_real_sources():
    shipped = json.loads((SCRIPT.parents[1] / "src/flake8_rosgraph/interfaces/standard.json").read_text())
    assert {s["repository"] for s in shipped["sources"]} >= {
        "github:ros2/common_interfaces", "github:ros2/rcl_interfaces", "github:ros2/example_interfaces",
        "github:ros2/geometry2", "github:ros2/unique_identifier_msgs", "github:ros2/demos"}
    assert all(len(commit) == 40 for s in shipped["sources"]
               for commit in ([s["commit"]] if "commit" in s else s["commits"].values()))
    assert "github:ros-navigation/navigation2" in {s["repository"] for s in shipped["sources"]}


def _branch(root: Path, ref: str, reading: str) -> None:
    base = root / f"fake_nav@{ref}" / "gamma_msgs"
    (base / "msg").mkdir(parents=True)
    (base / "package.xml").write_text("<package><name>gamma_msgs</name></package>")
    (base / "msg" / "Goal.msg").write_text("float64 x\n")
    (base / "msg" / "Status.msg").write_text(reading)
    (root / f"fake_nav@{ref}.commit").write_text(f"{ref}-commit\n")


def test_a_message_that_reads_differently_on_two_branches_is_left_out(script, tmp_path):
    """Read from each distribution's branch: a message whose fields changed between them would
    be wrong for one of them, so it is left out; the others are kept."""
    _branch(tmp_path, "humble", "uint8 state\n")
    _branch(tmp_path, "jazzy", "uint8 state\nstring detail\n")
    document = script.generate(tmp_path, {"example/fake_nav": ("gamma_msgs",)})
    assert document["sources"] == [{"repository": "github:example/fake_nav",
                                    "commits": {"humble": "humble-commit", "jazzy": "jazzy-commit"},
                                    "packages": ["gamma_msgs"]}]
    assert document["messages"] == {"gamma_msgs/msg/Goal": ["float64 x"]}
    assert document["differs"] == ["gamma_msgs/msg/Status"]
