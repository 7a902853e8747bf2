"""The C++ front end: rclcpp nodes and entities read from realistic packages, never a crash.

Each test writes a small colcon-style package (``package.xml``, ``include/``,
``src/``) and checks the nodes and entities :func:`cpp_graph` finds: the
construct under test, and the near-identical code that must give something else.
"""
from __future__ import annotations

import os
import textwrap
from pathlib import Path

import pytest

from flake8_rosgraph.cpp import extract, syntax, to_graph
from flake8_rosgraph.cpp.sources import MAX_CPP_FILE_BYTES
from flake8_rosgraph.cpp.to_graph import cpp_graph, interface_type

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>test</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <depend>rclcpp</depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""


def write_package(root: Path, name: str, files: dict[str, str]) -> Path:
    package = root / "src" / name
    package.mkdir(parents=True, exist_ok=True)
    (package / "package.xml").write_text(PACKAGE_XML.format(name=name))
    (package / "CMakeLists.txt").write_text(f"cmake_minimum_required(VERSION 3.8)\nproject({name})\n")
    for rel, text in files.items():
        path = package / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
    return package


def endpoints(root: Path) -> set[tuple]:
    """``(node fqn, kind, resolved name, type)`` of every named entity."""
    nodes, _ = cpp_graph(root)
    return {(n.fqn, e.kind, e.name, e.type) for n in nodes for e in n.entities if e.kind != "parameters"}


def diagnostics(root: Path) -> list:
    return cpp_graph(root)[1]


TALKER_HPP = """
    #pragma once
    #include "rclcpp/rclcpp.hpp"
    #include "std_msgs/msg/string.hpp"
    #include "std_srvs/srv/empty.hpp"

    namespace talker
    {
    class Talker : public rclcpp::Node
    {
    public:
      TALKER_PUBLIC
      explicit Talker(const rclcpp::NodeOptions & options);

    private:
      void on_timer();
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
      rclcpp::Service<std_srvs::srv::Empty>::SharedPtr reset_;
    };
    }  // namespace talker
"""

TALKER_CPP = """
    #include "talker/talker.hpp"
    #include "rclcpp_components/register_node_macro.hpp"

    namespace talker
    {
    Talker::Talker(const rclcpp::NodeOptions & options)
    : Node("talker", options)
    {
      pub_ = this->create_publisher<std_msgs::msg::String>("chatter", 10);
      reset_ = create_service<std_srvs::srv::Empty>("~/reset", [](auto, auto) {});
    }

    void Talker::on_timer()
    {
      auto sub = create_subscription<std_msgs::msg::String>("/feedback", 10, [](auto) {});
    }
    }  // namespace talker

    RCLCPP_COMPONENTS_REGISTER_NODE(talker::Talker)
"""


def test_class_declared_in_header_constructed_in_source(tmp_path):
    write_package(tmp_path, "talker", {"include/talker/talker.hpp": TALKER_HPP, "src/talker.cpp": TALKER_CPP})
    nodes, _ = cpp_graph(tmp_path)
    assert [(n.fqn, n.cls, n.language, n.location.short()) for n in nodes] == [
        ("/talker", "Talker", "cpp", "src/talker/src/talker.cpp:8")]
    assert endpoints(tmp_path) == {
        ("/talker", "publishers", "/chatter", "std_msgs/msg/String"),
        ("/talker", "services", "/talker/reset", "std_srvs/srv/Empty"),
        ("/talker", "subscriptions", "/feedback", "std_msgs/msg/String"),
    }
    publisher = next(e for n in nodes for e in n.entities if e.kind == "publishers")
    assert (publisher.location.line, publisher.location.column, publisher.qos) == (10, 10, {"depth": 10})


def test_namespace_and_private_names(tmp_path):
    write_package(tmp_path, "scanner", {"src/scanner.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "sensor_msgs/msg/laser_scan.hpp"
        class Scanner : public rclcpp::Node
        {
        public:
          Scanner() : rclcpp::Node("scanner", "robot1")
          {
            create_publisher<sensor_msgs::msg::LaserScan>("scan", 10);
            create_publisher<sensor_msgs::msg::LaserScan>("~/raw", 10);
            create_publisher<sensor_msgs::msg::LaserScan>("/global_scan", 10);
          }
        };
    """})
    assert {(fqn, name) for fqn, _, name, _ in endpoints(tmp_path)} == {
        ("/robot1/scanner", "/robot1/scan"), ("/robot1/scanner", "/robot1/scanner/raw"),
        ("/robot1/scanner", "/global_scan")}


def test_same_class_name_in_two_executables_of_one_package(tmp_path):
    body = """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        class MinimalPublisher : public rclcpp::Node
        {{
        public:
          MinimalPublisher() : Node("{node}")
          {{
            publisher_ = this->create_publisher<std_msgs::msg::String>("{topic}", 10);
          }}
          rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
        }};
    """
    write_package(tmp_path, "pubs", {"src/lambda.cpp": body.format(node="pub_a", topic="topic_a"),
                                     "src/member.cpp": body.format(node="pub_b", topic="topic_b")})
    assert endpoints(tmp_path) == {("/pub_a", "publishers", "/topic_a", "std_msgs/msg/String"),
                                   ("/pub_b", "publishers", "/topic_b", "std_msgs/msg/String")}


def test_entities_of_a_base_class_belong_to_the_derived_nodes(tmp_path):
    write_package(tmp_path, "drivers", {
        "include/drivers/driver_base.hpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "std_msgs/msg/float64.hpp"
            class DriverBase : public rclcpp::Node
            {
            public:
              explicit DriverBase(const std::string & name) : Node(name)
              {
                temperature_ = create_publisher<std_msgs::msg::Float64>("temperature", 10);
              }
            protected:
              rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr temperature_;
            };
        """,
        "src/left.cpp": """
            #include "drivers/driver_base.hpp"
            class LeftDriver : public DriverBase
            {
            public:
              LeftDriver() : DriverBase("left_driver") {}
            };
        """,
        "src/helper.cpp": """
            #include "rclcpp/rclcpp.hpp"
            class Counter
            {
            public:
              Counter() : Base("not_a_node"), count_(0) {}
              int count_;
            };
        """,
    })
    nodes, _ = cpp_graph(tmp_path)
    assert sorted(n.fqn for n in nodes) == ["/left_driver"]
    assert endpoints(tmp_path) == {("/left_driver", "publishers", "/temperature", "std_msgs/msg/Float64")}


def test_a_plugin_source_that_names_rclcpp_only_through_its_header(tmp_path):
    write_package(tmp_path, "filters", {
        "include/filters/speed_filter.hpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "nav2_msgs/msg/speed_limit.hpp"
            using NodePtr = std::shared_ptr<rclcpp::Node>;
            class SpeedFilter
            {
            public:
              void activate(NodePtr node);
            };
        """,
        "src/speed_filter.cpp": """
            #include "filters/speed_filter.hpp"
            void SpeedFilter::activate(NodePtr node)
            {
              node->create_publisher<nav2_msgs::msg::SpeedLimit>("/speed_limit", 1);
            }
        """,
        "src/math.cpp": """
            #include "filters/speed_filter.hpp"
            double clamp(double v) { return v < 0 ? 0 : v; }
        """,
    })
    assert endpoints(tmp_path) == {(None, "publishers", "/speed_limit", "nav2_msgs/msg/SpeedLimit")}


def test_names_from_constants_of_the_same_file(tmp_path):
    write_package(tmp_path, "consts", {"src/node.cpp": """
        #include <string>
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        #define STATUS_TOPIC "status"
        namespace
        {
        constexpr char kEvents[] = "events";
        const std::string kPrefix = "/robot";
        }
        class Reporter : public rclcpp::Node
        {
        public:
          static constexpr const char * kAlarm = "alarm";
          Reporter() : Node("reporter"), log_topic_("log")
          {
            cmd_topic_ = kPrefix + std::string("/cmd");
            std::string diag = "diag";
            create_publisher<std_msgs::msg::String>(STATUS_TOPIC, 10);
            create_publisher<std_msgs::msg::String>(kEvents, 10);
            create_publisher<std_msgs::msg::String>(kAlarm, 10);
            create_publisher<std_msgs::msg::String>(log_topic_, 10);
            create_publisher<std_msgs::msg::String>(this->cmd_topic_, 10);
            create_publisher<std_msgs::msg::String>(diag.c_str(), 10);
          }
          std::string log_topic_;
          std::string cmd_topic_;
        };
    """})
    assert {name for _, _, name, _ in endpoints(tmp_path)} == {
        "/status", "/events", "/alarm", "/log", "/robot/cmd", "/diag"}


def test_a_variable_given_an_unknown_value_somewhere_is_unknown(tmp_path):
    write_package(tmp_path, "mixed", {"src/node.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        std::string pick(int i);
        class Relay : public rclcpp::Node
        {
        public:
          Relay() : Node("relay")
          {
            std::string topic = "input";
            if (true) {
              topic = pick(3);
            }
            create_subscription<std_msgs::msg::String>(topic, 10, [](auto) {});
          }
        };
    """})
    assert endpoints(tmp_path) == {("/relay", "subscriptions", None, "std_msgs/msg/String")}


def test_names_from_parameter_defaults_keep_an_unknown_alternative(tmp_path):
    write_package(tmp_path, "params", {"src/node.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "sensor_msgs/msg/laser_scan.hpp"
        #include "nav_msgs/msg/odometry.hpp"
        class Filter : public rclcpp::Node
        {
        public:
          Filter() : Node("filter")
          {
            auto input = declare_parameter<std::string>("input_topic", "scan");
            this->declare_parameter("output_topic", "scan_filtered");
            declare_parameter("odom_topic", rclcpp::ParameterValue(std::string("odom")));
            declare_parameter("rate", 10.0);
            get_parameter("odom_topic", odom_topic_);
            create_subscription<sensor_msgs::msg::LaserScan>(input, 10, [](auto) {});
            create_publisher<sensor_msgs::msg::LaserScan>(
              this->get_parameter("output_topic").as_string(), 10);
            create_subscription<nav_msgs::msg::Odometry>(odom_topic_, 10, [](auto) {});
          }
          std::string odom_topic_;
        };
    """})
    nodes, _ = cpp_graph(tmp_path)
    assert {(e.kind, e.name) for n in nodes for e in n.entities if e.kind != "parameters"} == {
        ("subscriptions", "/scan"), ("subscriptions", None),
        ("publishers", "/scan_filtered"), ("publishers", None),
        ("subscriptions", "/odom")}
    assert {(e.name, e.default) for n in nodes for e in n.entities if e.kind == "parameters"} == {
        ("input_topic", "scan"), ("output_topic", "scan_filtered"), ("odom_topic", "odom"), ("rate", 10.0)}


def test_nodes_made_in_main_and_their_receivers(tmp_path):
    write_package(tmp_path, "mains", {
        "src/shared.cpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "std_msgs/msg/string.hpp"
            rclcpp::Node::SharedPtr g_node = nullptr;
            int main(int argc, char ** argv)
            {
              rclcpp::init(argc, argv);
              auto node = std::make_shared<rclcpp::Node>("alpha");
              node->create_publisher<std_msgs::msg::String>("a_out", 10);
              g_node = rclcpp::Node::make_shared("beta", "tools");
              g_node->create_subscription<std_msgs::msg::String>("b_in", 10, [](auto) {});
              rclcpp::Node local("gamma");
              local.create_publisher<std_msgs::msg::String>("c_out", 10);
              rclcpp::spin(node);
              g_node = nullptr;
              return 0;
            }
        """,
        "src/plugin.cpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "std_msgs/msg/string.hpp"
            class Layer
            {
            public:
              void configure(rclcpp::Node::WeakPtr parent)
              {
                auto node = parent.lock();
                node->create_subscription<std_msgs::msg::String>("relative", 10, [](auto) {});
                node->create_subscription<std_msgs::msg::String>("/absolute", 10, [](auto) {});
              }
            };
        """,
    })
    assert endpoints(tmp_path) == {
        ("/alpha", "publishers", "/a_out", "std_msgs/msg/String"),
        ("/tools/beta", "subscriptions", "/tools/b_in", "std_msgs/msg/String"),
        ("/gamma", "publishers", "/c_out", "std_msgs/msg/String"),
        # A plugin's host node is not known: relative names stay unknown, absolute ones are kept.
        (None, "subscriptions", None, "std_msgs/msg/String"),
        (None, "subscriptions", "/absolute", "std_msgs/msg/String"),
    }


def test_constructor_arguments_from_the_constructions_of_the_file(tmp_path):
    write_package(tmp_path, "rates", {"src/rates.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        class Talker : public rclcpp::Node
        {
        public:
          Talker(const std::string & node_name, const std::string & topic_name)
          : Node(node_name)
          {
            publisher_ = this->create_publisher<std_msgs::msg::String>(topic_name, 10);
          }
          rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
        };
        int main()
        {
          auto a = std::make_shared<Talker>("talker_a", "topic_a");
          auto b = std::make_shared<Talker>("talker_b", "topic_b");
        }
    """})
    found = endpoints(tmp_path)
    assert {fqn for fqn, *_ in found} == {"/talker_a", "/talker_b"}
    assert {name for _, _, name, _ in found} == {"/topic_a", "/topic_b"}


def test_services_and_actions_in_every_spelling(tmp_path):
    write_package(tmp_path, "actions", {"src/server.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "rclcpp_action/rclcpp_action.hpp"
        #include "example_interfaces/action/fibonacci.hpp"
        #include "example_interfaces/srv/add_two_ints.hpp"
        using example_interfaces::srv::AddTwoInts;
        typedef example_interfaces::action::Fibonacci Fib;
        class Server : public rclcpp::Node
        {
        public:
          using Fibonacci = Fib;
          Server() : Node("server")
          {
            server_ = rclcpp_action::create_server<Fibonacci>(this, "fibonacci", a, b, c);
            other_ = rclcpp_action::create_server<Fibonacci>(
              this->get_node_base_interface(), this->get_node_clock_interface(),
              this->get_node_logging_interface(), this->get_node_waitables_interface(), "fibonacci_legacy",
              a, b, c);
            client_ = rclcpp_action::create_client<Fibonacci>(shared_from_this(), "remote_fibonacci");
            add_ = create_service<AddTwoInts>("add_two_ints", cb);
            call_ = create_client<AddTwoInts>("remote_add");
            base_ = rclcpp::Node::create_client<AddTwoInts>("base_add");
            free_ = rclcpp::create_client<AddTwoInts>(
              get_node_base_interface(), get_node_graph_interface(), get_node_services_interface(),
              "free_add", rclcpp::ServicesQoS(), nullptr);
          }
        };
    """})
    fib, add = "example_interfaces/action/Fibonacci", "example_interfaces/srv/AddTwoInts"
    assert endpoints(tmp_path) == {
        ("/server", "action_servers", "/fibonacci", fib), ("/server", "action_servers", "/fibonacci_legacy", fib),
        ("/server", "action_clients", "/remote_fibonacci", fib),
        ("/server", "services", "/add_two_ints", add), ("/server", "clients", "/remote_add", add),
        ("/server", "clients", "/base_add", add), ("/server", "clients", "/free_add", add)}


def test_interface_type_spellings():
    aliases = ({"Msg": "std_msgs::msg::String", "Chain": "Msg"},)
    assert interface_type("std_msgs::msg::String", ()) == "std_msgs/msg/String"
    assert interface_type("::nav2_msgs::action::DockRobot", ()) == "nav2_msgs/action/DockRobot"
    assert interface_type("Chain", aliases) == "std_msgs/msg/String"
    assert interface_type("MsgT", aliases) is None
    assert interface_type("std_msgs::msg::String::SharedPtr", ()) is None
    own = frozenset({"fleet::msg::Status"})
    assert interface_type("msg::Status", (), "fleet::detail", own) == "fleet/msg/Status"
    assert interface_type("msg::Status", (), "tools", own) is None
    assert interface_type("msg::Other", (), "fleet", own) is None
    assert interface_type("::msg::Status", (), "fleet", own) is None


def test_a_relative_type_in_the_packages_namespace_is_its_own_interface(tmp_path):
    """``msg::VehicleState`` inside ``namespace fleet`` of package ``fleet`` is the package's own
    ``fleet/msg/VehicleState`` (also in a member defined outside the namespace); a loop over
    topic names keeps the end as an unknown name of that type. Twins: the same spelling in
    another namespace (a ``using namespace`` may make ``msg`` any package's) and at file scope
    stay unknown."""
    write_package(tmp_path, "fleet", {"msg/VehicleState.msg": "string id\nfloat64 x\n", "src/referee.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "fleet/msg/vehicle_state.hpp"
        namespace fleet {
        namespace detail {
        constexpr char kStatus[] = "/fleet/status";
        }
        class Referee : public rclcpp::Node {
        public:
          explicit Referee(const std::vector<std::string> & topics) : Node("referee") {
            for (const auto & topic : topics) {
              subs_.push_back(create_subscription<msg::VehicleState>(topic, 10, [](msg::VehicleState::SharedPtr) {}));
            }
            status_ = create_publisher<msg::VehicleState>(detail::kStatus, 10);
          }
          void start();
        private:
          std::vector<rclcpp::Subscription<msg::VehicleState>::SharedPtr> subs_;
          rclcpp::Publisher<msg::VehicleState>::SharedPtr status_;
        };
        }  // namespace fleet
        void fleet::Referee::start() {
          create_publisher<msg::VehicleState>("/fleet/started", 10);
        }
        namespace tools {
        class Probe : public rclcpp::Node {
        public:
          Probe() : Node("probe") { create_publisher<msg::VehicleState>("/probe", 10); }
        };
        }
    """})
    state = "fleet/msg/VehicleState"
    assert endpoints(tmp_path) == {
        ("/referee", "subscriptions", None, state), ("/referee", "publishers", "/fleet/status", state),
        ("/referee", "publishers", "/fleet/started", state), ("/probe", "publishers", "/probe", None)}


def test_an_end_with_unknown_name_and_type_is_left_out_with_a_diagnostic(tmp_path):
    write_package(tmp_path, "generic", {"include/generic/watch.hpp": """
        #include "rclcpp/rclcpp.hpp"
        template<typename MsgT>
        void watch(rclcpp::Node * node, const std::string & topic)
        {
          node->create_subscription<MsgT>(topic, 10, [](typename MsgT::SharedPtr) {});
        }
        template<typename MsgT>
        void advertise(rclcpp::Node * node)
        {
          node->create_publisher<MsgT>("/fixed", 10);
        }
    """})
    nodes, diags = cpp_graph(tmp_path)
    assert [(e.kind, e.name, e.type) for n in nodes for e in n.entities] == [("publishers", "/fixed", None)]
    assert [(d.path, d.line, d.severity) for d in diags if "unknown name and type" in d.message] == [
        ("src/generic/include/generic/watch.hpp", 6, "info")]


def test_damaged_file_is_a_diagnostic_and_its_other_calls_still_count(tmp_path):
    write_package(tmp_path, "damaged", {
        "src/damaged.cpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "std_msgs/msg/bool.hpp"
            class Dock : public rclcpp::Node
            {
            public:
              Dock() : Node("dock")
              {
                create_publisher<std_msgs::msg::Bool>("is_charging", 1);
              }
              void undock();
            };
            void Dock::undock(
            {
              create_publisher<std_msgs::msg::Bool>("undocked" 1;
        """,
        "src/macro.cpp": """
            #include "rclcpp/rclcpp.hpp"
            #include "std_msgs/msg/bool.hpp"
            class Beacon : public rclcpp::Node
            {
            public:
              BEACON_PUBLIC
              explicit Beacon() : Node("beacon") { create_publisher<std_msgs::msg::Bool>("beacon", 1); }
            };
        """,
    })
    nodes, diags = cpp_graph(tmp_path)
    assert endpoints(tmp_path) == {("/dock", "publishers", "/is_charging", "std_msgs/msg/Bool"),
                                   ("/beacon", "publishers", "/beacon", "std_msgs/msg/Bool")}
    by_file = {d.path: d for d in diags}
    assert by_file["src/damaged/src/damaged.cpp"].severity == "warning"
    assert "syntax error" in by_file["src/damaged/src/damaged.cpp"].message
    assert by_file["src/damaged/src/macro.cpp"].severity == "info"


def test_discovery_respects_packages_ignore_markers_build_folders_and_limits(tmp_path):
    node = """
        #include "rclcpp/rclcpp.hpp"
        #include "std_msgs/msg/string.hpp"
        int main() {{ auto n = rclcpp::Node::make_shared("{name}"); }}
    """
    write_package(tmp_path, "kept", {"src/kept.cpp": node.format(name="kept")})
    write_package(tmp_path, "ignored", {"src/ignored.cpp": node.format(name="ignored")})
    (tmp_path / "src" / "ignored" / "COLCON_IGNORE").write_text("")
    write_package(tmp_path, "built", {"build/gen.cpp": node.format(name="built"),
                                      ".hidden/gen.cpp": node.format(name="hidden"),
                                      "test/test_node.cpp": node.format(name="gtest_node")})
    (tmp_path / "tools").mkdir()
    (tmp_path / "tools" / "loose.cpp").write_text(textwrap.dedent(node.format(name="loose")))
    write_package(tmp_path, "plain", {"src/math.cpp": "int add(int a, int b) { return a + b; }\n"})
    big = tmp_path / "src" / "kept" / "src" / "generated.cpp"
    big.write_text("// rclcpp\n" + "int x;\n" * (MAX_CPP_FILE_BYTES // 6))
    if hasattr(os, "mkfifo"):
        os.mkfifo(tmp_path / "src" / "kept" / "src" / "pipe.cpp")
    nodes, diags = cpp_graph(tmp_path)
    assert [n.fqn for n in nodes] == ["/kept"]
    messages = {d.path: d.message for d in diags}
    assert "larger than" in messages["src/kept/src/generated.cpp"]
    if hasattr(os, "mkfifo"):
        assert "not a regular file" in messages["src/kept/src/pipe.cpp"]


def test_syntax_node_budget_is_a_diagnostic(tmp_path, monkeypatch):
    write_package(tmp_path, "big", {"src/talker.cpp": TALKER_CPP})
    _, diags = cpp_graph(tmp_path)
    assert not any("read in part" in d.message for d in diags)
    monkeypatch.setattr(extract, "MAX_SYNTAX_NODES", 5)
    _, diags = cpp_graph(tmp_path)
    assert any("read in part" in d.message and d.path == "src/big/src/talker.cpp" for d in diags)


def test_hostile_sources_never_crash(tmp_path):
    nested = "#include \"rclcpp/rclcpp.hpp\"\nint f() { return " + "(" * 20000 + "1" + ")" * 20000 + "; }\n"
    chain = "#include <rclcpp/rclcpp.hpp>\nstd::string t = " + " + ".join(['"a"'] * 5000) + ";\n" \
        "int main() { auto n = rclcpp::Node::make_shared(\"n\"); n->create_publisher<std_msgs::msg::String>(t, 1); }\n"
    write_package(tmp_path, "hostile", {"src/nested.cpp": nested, "src/chain.cpp": chain})
    (tmp_path / "src" / "hostile" / "src" / "binary.cpp").write_bytes(b"rclcpp\x00\xff\xfe" * 1000)
    nodes, _ = cpp_graph(tmp_path)
    assert [(n.fqn, [(e.name, e.type) for e in n.entities]) for n in nodes] == [
        ("/n", [(None, "std_msgs/msg/String")])]


def test_without_tree_sitter_the_python_graph_still_builds(tmp_path, monkeypatch):
    monkeypatch.setattr(to_graph, "load_parser", lambda: (None, "C++ sources not read: tree_sitter is not installed"))
    write_package(tmp_path, "talker", {"src/talker.cpp": TALKER_CPP})
    nodes, diags = cpp_graph(tmp_path)
    assert nodes == [] and [d.message for d in diags] == ["C++ sources not read: tree_sitter is not installed"]


def test_parser_loads_with_the_modern_api():
    parser, why_not = syntax.load_parser()
    assert why_not is None
    tree = parser.parse(b'auto n = rclcpp::Node::make_shared("x");')
    assert not tree.root_node.has_error


@pytest.mark.parametrize("name", ["declare_parameter", "declare_parameter_if_not_declared",
                                  "declare_or_get_parameter"])
def test_declare_parameter_spellings(name):
    from flake8_rosgraph.cpp.values import is_declare_parameter
    assert is_declare_parameter(name)
    assert not is_declare_parameter("declare_parameters")


def test_an_internal_error_in_one_file_costs_only_that_file(tmp_path, monkeypatch):
    write_package(tmp_path, "two", {"src/talker.cpp": TALKER_CPP, "src/other.cpp": """
        #include "rclcpp/rclcpp.hpp"
        int main() { auto n = rclcpp::Node::make_shared("other"); }
    """})
    real = to_graph.read_file

    def failing(source, parser):
        if source.path.endswith("talker.cpp"):
            raise KeyError("boom")
        return real(source, parser)

    monkeypatch.setattr(to_graph, "read_file", failing)
    nodes, diags = cpp_graph(tmp_path)
    assert [n.fqn for n in nodes] == ["/other"]
    assert [(d.path, d.severity) for d in diags if "internal error" in d.message] == [
        ("src/two/src/talker.cpp", "error")]


def test_generic_publishers_and_subscriptions_take_the_type_as_a_string(tmp_path):
    """A bag player publishes what it reads with ``create_generic_publisher(name, "pkg/msg/T", qos)``."""
    write_package(tmp_path, "bag_tools", {"src/player.cpp": """
        #include "rclcpp/rclcpp.hpp"

        static const char * kType = "sensor_msgs/msg/Imu";

        class Player : public rclcpp::Node
        {
        public:
          Player() : Node("player")
          {
            imu_ = create_generic_publisher("imu", kType, rclcpp::QoS(5));
            odom_ = this->create_generic_subscription(
              "odom", "nav_msgs/msg/Odometry", 10, [](std::shared_ptr<rclcpp::SerializedMessage>) {});
            other_ = create_generic_publisher("replayed", topic_type_, 10);
          }
        private:
          std::string topic_type_;
          rclcpp::GenericPublisher::SharedPtr imu_, other_;
          rclcpp::GenericSubscription::SharedPtr odom_;
        };
        """})
    found = endpoints(tmp_path)
    assert ("/player", "publishers", "/imu", "sensor_msgs/msg/Imu") in found
    assert ("/player", "subscriptions", "/odom", "nav_msgs/msg/Odometry") in found
    assert ("/player", "publishers", "/replayed", None) in found  # a type only known at run time


def test_a_node_name_passed_through_a_constructor_has_the_root_namespace(tmp_path):
    """``Node(name)`` runs in ``/`` (rcl maps the empty namespace to the root): no name problem
    (aws-deepracer's ``CtrlNodeMgr(nodeName) : Node(nodeName)`` was marked "namespace '' is empty");
    a namespace given with a trailing slash still is one."""
    write_package(tmp_path, "vehicle_ctrl", {"src/ctrl_node.cpp": """
        #include "rclcpp/rclcpp.hpp"
        #include "std_srvs/srv/trigger.hpp"
        class CtrlNodeMgr : public rclcpp::Node
        {
        public:
          explicit CtrlNodeMgr(const std::string & node_name) : Node(node_name) {}
        };
        class BadNs : public rclcpp::Node
        {
        public:
          BadNs() : Node("bad_ns", "robot/") {}
        };
        int main(int argc, char ** argv)
        {
          rclcpp::init(argc, argv);
          auto node = std::make_shared<CtrlNodeMgr>("control_node");
          rclcpp::spin(node);
        }
    """})
    nodes, _ = cpp_graph(tmp_path)
    assert {(n.fqn, n.invalid) for n in nodes} == {
        ("/control_node", None), ("/robot/bad_ns", "namespace '/robot/' ends with '/'")}
