"""Python the analysis does not follow is named by a diagnostic at the place it happens."""


def messages(analysed) -> list[tuple[str, int, str]]:
    return sorted({(d.path, d.line, d.message.split(":")[0]) for d in analysed.analysis.diagnostics
                   if d.severity == "warning"})


def test_exec_eval_and_a_workspace_metaclass_are_named(analyse):
    analysis = analyse({"plugins/registry.py": """
        import rclpy
        from rclpy.node import Node


        class Registry(type):
            def __call__(cls, *args):
                return super().__call__(*args)


        class Camera(Node, metaclass=Registry):
            def __init__(self, name):
                super().__init__(name)
                exec('self.pub = self.create_publisher(Image, "image", 10)')


        def topic_for(expr):
            return eval(expr)


        Camera('camera')
        topic_for('"a" + "b"')
    """})
    assert messages(analysis) == [
        ("plugins/registry.py", 11, "the metaclass of Camera is not followed"),
        ("plugins/registry.py", 14, "exec() runs code the analysis does not follow"),
        ("plugins/registry.py", 18, "eval() runs code the analysis does not follow"),
    ]


def test_library_metaclasses_and_plain_calls_stay_quiet(analyse):
    analysis = analyse({"plugins/registry.py": """
        import abc
        import rclpy
        from rclpy.node import Node


        class Camera(Node, metaclass=abc.ABCMeta):
            def __init__(self, name):
                super().__init__(name)
                self.pub = self.create_publisher(Image, 'image', 10)


        def topic_for(expr):
            return str(expr)


        Camera('camera')
        topic_for('"a" + "b"')
    """})
    assert messages(analysis) == []
