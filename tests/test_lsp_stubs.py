"""The language server reads the user's stubs (`stub-paths` in the document's
`[tool.robotfix]`), as `robotfix check` does: it read only the shipped ones, so the
editor missed what the command line reported (issue 24 item 3)."""

from __future__ import annotations

from pathlib import Path

from tests.lsp_client import Client

SOURCE = """from typing import Annotated
import mylib

PERIOD: Annotated[float, "Unit('ms')"] = 100.0
mylib.wait(PERIOD)
took = mylib.elapsed()
"""


STUB = (
    "from typing import Annotated\n"
    "def wait(duration: Annotated[float, \"Unit('s')\"]) -> None: ...\n"
    "def elapsed() -> Annotated[float, \"Unit('s')\"]: ...\n"
)


def _project(tmp_path: Path) -> tuple[Path, Path]:
    """A package whose `stub-paths` holds `mylib.pyi`, and its node: (stub, node)."""
    (tmp_path / "pyproject.toml").write_text(
        '[tool.robotfix]\nstub-paths = ["stubs"]\n', encoding="utf-8"
    )
    (tmp_path / "stubs").mkdir()
    stub = tmp_path / "stubs" / "mylib.pyi"
    stub.write_text(STUB, encoding="utf-8")
    path = tmp_path / "node.py"
    path.write_text(SOURCE, encoding="utf-8")
    return stub, path


def test_the_editor_checks_and_hovers_with_the_users_stubs(tmp_path: Path) -> None:
    _, path = _project(tmp_path)
    client = Client()
    try:
        client.initialize(tmp_path)
        uri = client.open(path, SOURCE)
        opened = client.diagnostics()
        hover = client.hover(uri, 5, 1)
        client.stop()
    finally:
        client.kill()
    found = [(d["code"], d["range"]["start"]["line"]) for d in opened["diagnostics"]]
    assert found == [("RF201", 4)]  # ms into the stub's s
    assert "`s`" in hover["result"]["contents"]["value"]


def test_a_stub_changed_on_disk_is_read_again(tmp_path: Path) -> None:
    """The server kept every stub it had read for its whole life: a user who
    corrected a stub's unit saw the old diagnostics until the editor restarted.
    A `.pyi` reported changed (watched files) or saved is read again, and the open
    Python documents are checked again."""
    stub, path = _project(tmp_path)
    client = Client()
    try:
        client.initialize(tmp_path)
        client.open(path, SOURCE)
        before = client.diagnostics()
        stub.write_text(STUB.replace("'s'", "'ms'", 1), encoding="utf-8")
        client.notify(
            "workspace/didChangeWatchedFiles",
            {"changes": [{"uri": stub.as_uri(), "type": 2}]},
        )
        watched = client.diagnostics()
        stub.write_text(STUB, encoding="utf-8")
        client.notify("textDocument/didSave", {"textDocument": {"uri": stub.as_uri()}})
        saved = client.diagnostics()
        client.stop()
    finally:
        client.kill()
    assert [d["code"] for d in before["diagnostics"]] == ["RF201"]
    assert watched["uri"] == path.as_uri() and watched["diagnostics"] == []
    assert saved["uri"] == path.as_uri()
    assert [d["code"] for d in saved["diagnostics"]] == ["RF201"]
