"""Call sites the engine records per task: user calls to tasks, library calls by qualified name."""
from flake8_rosgraph.absint.values import Obj

from test_engine import run

FILES = {
    "pkg/__init__.py": "",
    "pkg/helpers.py": """
        def fetch(client, request):
            return client.call(request)

        def shout(text):
            if text:
                return text.upper()
    """,
    "pkg/node.py": """
        import rclpy
        from std_srvs.srv import Trigger
        from pkg import helpers

        def main(flag):
            node = rclpy.create_node('n')
            client = node.create_client(Trigger, 'reset')
            helpers.fetch(client, Trigger.Request())
            if flag:
                helpers.shout('x')
            try:
                helpers.shout('y')
            except ValueError:
                pass
            helpers.shout(flag)
    """,
}


def _function(analysis, qualname):
    return next(f.fid for f in analysis.program.functions if f.qualname == qualname)


def test_calls_to_workspace_functions_and_library_models_are_recorded(tmp_path):
    analysis = run(tmp_path, FILES, every_module_is_entry=True)
    graph = analysis.call_graph()
    [main] = graph.tasks_of(_function(analysis, "main"))
    sites = graph.sites(main)
    described = [(s.line, s.callee[0], s.callee[1] if s.callee[0] == "lib" else
                  analysis.program.functions[s.callee[1][1]].qualname, s.conditional, s.guarded)
                 for s in sites]
    assert described == [
        (7, "lib", "rclpy.create_node", False, False),
        (8, "lib", "rclpy.node.Node.create_client", False, False),
        (9, "task", "fetch", False, False),
        (11, "task", "shout", True, False),
        (13, "task", "shout", False, True),
        (16, "task", "shout", False, False),
    ]
    create_client = sites[1]
    assert create_client.text() == "node.create_client"
    assert [e.kind for e in create_client.effects] == ["client"]
    assert create_client.arg("srv_name").strings() == ["reset"]
    assert all(isinstance(a, Obj) for a in create_client.arg("self"))


def test_the_callee_task_records_the_library_call_on_its_argument(tmp_path):
    analysis = run(tmp_path, FILES, every_module_is_entry=True)
    graph = analysis.call_graph()
    [main] = graph.tasks_of(_function(analysis, "main"))
    fetch_task = next(s.callee[1] for s in graph.sites(main) if s.callee[0] == "task")
    [call] = graph.sites(fetch_task)
    assert call.callee == ("lib", "rclpy.client.Client.call")
    assert analysis.library.method("rclpy.client.Client", "call").blocking


def test_a_body_that_may_end_without_return_is_noted(tmp_path):
    analysis = run(tmp_path, FILES, every_module_is_entry=True)
    graph = analysis.call_graph()
    shout = graph.tasks_of(_function(analysis, "shout"))
    fetch = graph.tasks_of(_function(analysis, "fetch"))
    unknown = [t for t in shout if t[2][0].is_top]
    known = [t for t in shout if not t[2][0].is_top]
    # shout(flag) with flag unknown may fall off the end.
    assert unknown and all(task in analysis.falls_off for task in unknown)
    # shout('x') decides `if text:`: the path that falls off the end is never taken.
    assert known and not any(task in analysis.falls_off for task in known)
    assert fetch and not any(task in analysis.falls_off for task in fetch)


def test_a_library_call_knows_what_the_excepts_around_it_catch(tmp_path):
    """The ``except`` clauses of every ``try`` around a modelled call with effects, innermost
    first, by qualified name; a bare ``except:`` catches ``BaseException``; a computed class
    is ``?``; the handler's own body and the ``else`` are outside the ``try``."""
    files = {"pkg/__init__.py": "", "pkg/params.py": """
        from rclpy.exceptions import ParameterNotDeclaredException
        import rclpy.exceptions

        class LocalError(Exception):
            pass

        def errors():
            return (KeyError,)

        def read(node):
            try:
                try:
                    node.get_parameter('a')
                except (ParameterNotDeclaredException, LocalError):
                    node.get_parameter('b')
                else:
                    node.get_parameter('c')
            except rclpy.exceptions.ParameterException:
                pass
            except:
                pass
            try:
                node.get_parameter('d')
            except errors():
                pass
            node.get_parameter('e')

        def main():
            read(rclpy.create_node('n'))
    """}
    analysis = run(tmp_path, files, every_module_is_entry=True)
    graph = analysis.call_graph()
    [read] = graph.tasks_of(_function(analysis, "read"))
    caught = [(s.line, s.caught) for s in graph.sites(read) if s.callee == ("lib", "rclpy.node.Node.get_parameter")]
    assert caught == [
        (14, ("rclpy.exceptions.ParameterNotDeclaredException", "LocalError",
              "rclpy.exceptions.ParameterException", "builtins.BaseException")),
        (16, ("rclpy.exceptions.ParameterException", "builtins.BaseException")),
        (18, ("rclpy.exceptions.ParameterException", "builtins.BaseException")),
        (24, ("?",)),
        (27, ()),
    ]
