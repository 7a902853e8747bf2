"""python-lsp-server's flake8 plugin, driven over the language server protocol as an editor drives it.

pylsp sends the unsaved buffer to ``flake8 -`` with ``--stdin-display-name``; the
findings must follow the buffer (a typo typed but not saved is reported at its
line; fixing it in the buffer clears it) while the file on disk stays untouched.
Skipped when python-lsp-server is not installed (it is in the ``test`` extra).
"""
from __future__ import annotations

import json
import queue
import shutil
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any, BinaryIO

import pytest

from .conftest import EXAMPLES, clean_env

pytest.importorskip("pylsp", reason="python-lsp-server is not installed (pip install -e '.[test]')")

CONSUMERS = "src/thesis_graph/thesis_graph/consumers.py"
WAIT_SECONDS = 240


class LanguageClient:
    """The few requests and notifications an editor sends, and the diagnostics it is sent back."""

    def __init__(self, root: Path) -> None:
        self.process = subprocess.Popen([sys.executable, "-m", "pylsp"], cwd=root, stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=clean_env())
        self.inbox: queue.Queue[dict[str, Any]] = queue.Queue()
        assert self.process.stdout is not None
        threading.Thread(target=self._read, args=(self.process.stdout,), daemon=True).start()
        self.next_id = 0

    def _read(self, stream: BinaryIO) -> None:
        while True:
            length = 0
            while (header := stream.readline()) not in (b"\r\n", b""):
                if header.lower().startswith(b"content-length:"):
                    length = int(header.split(b":")[1])
            if not header:
                return
            self.inbox.put(json.loads(stream.read(length)))

    def send(self, method: str, params: dict[str, Any], request: bool = False) -> int | None:
        message: dict[str, Any] = {"jsonrpc": "2.0", "method": method, "params": params}
        if request:
            self.next_id += 1
            message["id"] = self.next_id
        body = json.dumps(message).encode()
        assert self.process.stdin is not None
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()
        return message.get("id")

    def diagnostics(self, uri: str) -> list[dict[str, Any]]:
        """The next diagnostics published for ``uri``."""
        while True:
            message = self.inbox.get(timeout=WAIT_SECONDS)
            if message.get("method") == "textDocument/publishDiagnostics" and message["params"]["uri"] == uri:
                return message["params"]["diagnostics"]

    def close(self) -> None:
        self.send("shutdown", {}, request=True)
        self.send("exit", {})
        try:
            self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.process.kill()


def _ros_codes(diagnostics: list[dict[str, Any]]) -> list[tuple[int, str]]:
    """(1-based line, code) of the ROS diagnostics; pylsp puts the code in ``code``."""
    return sorted((d["range"]["start"]["line"] + 1, str(d.get("code")))
                  for d in diagnostics if str(d.get("code", "")).startswith("ROS"))


def test_pylsp_reports_the_unsaved_buffer(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    shutil.copytree(EXAMPLES, root)
    (root / ".git").mkdir()
    path = root / CONSUMERS
    saved = path.read_text()
    flake8 = Path(sys.executable).with_name("flake8")
    client = LanguageClient(root)
    try:
        client.send("initialize", {"processId": None, "rootUri": root.as_uri(), "capabilities": {}}, request=True)
        client.send("initialized", {})
        client.send("workspace/didChangeConfiguration", {"settings": {"pylsp": {"plugins": {
            "flake8": {"enabled": True, "select": ["ROS"], "executable": str(flake8)},
            "pycodestyle": {"enabled": False}, "pyflakes": {"enabled": False}, "mccabe": {"enabled": False},
        }}}})
        uri = path.as_uri()
        client.send("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "python", "version": 1, "text": saved}})
        on_open = _ros_codes(client.diagnostics(uri))
        assert (20, "ROS003") in on_open, on_open  # the example's consumer of a topic nobody publishes

        # the user copies the topic4 subscription above the ROS003 one, misspells it, and does not save
        lines = saved.splitlines(keepends=True)
        at = next(i for i, line in enumerate(lines) if "'topic4'" in line)
        edited = "".join(lines[:at + 1] + [lines[at].replace("'topic4'", "'topic44'")] + lines[at + 1:])
        client.send("textDocument/didChange", {"textDocument": {"uri": uri, "version": 2},
                                               "contentChanges": [{"text": edited}]})
        on_edit = _ros_codes(client.diagnostics(uri))
        # the typo at line 20 and the old finding moved to line 21: the buffer's lines, not the disk's
        assert (at + 2, "ROS003") in on_edit and (21, "ROS003") in on_edit, on_edit

        client.send("textDocument/didChange", {"textDocument": {"uri": uri, "version": 3},
                                               "contentChanges": [{"text": saved}]})
        assert _ros_codes(client.diagnostics(uri)) == on_open
    finally:
        client.close()
    assert path.read_text() == saved
