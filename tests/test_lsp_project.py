"""The language server keeps the module summaries of a document's imports across
keystrokes (`server._project`), and builds them again when what they were read from
changes on disk, even when no editor told it: an imported module edited in place, a
module created next to the document, a Python file saved."""

from __future__ import annotations

import os
from pathlib import Path

from robotfix import api
from robotfix.lsp import server
from tests.lsp_client import Client

HELPER = (
    "from typing import Annotated\n\n"
    "SPEED: Annotated[float, \"Unit('{unit}')\"] = 3.0\n"
)
NODE = """from geometry_msgs.msg import Twist
from helper import SPEED
from extra import TURN

cmd = Twist()
cmd.linear.x = SPEED
cmd.angular.z = TURN
"""
EXTRA = (
    "from typing import Annotated\n\nTURN: Annotated[float, \"Unit('deg/s')\"] = 9.0\n"
)


def _later(path: Path) -> None:
    """Move a file's times a second on, as an edit by hand a second later would
    (a coarse file-system clock cannot hide it)."""
    stamp = os.stat(path)
    os.utime(path, ns=(stamp.st_atime_ns, stamp.st_mtime_ns + 1_000_000_000))


def test_summaries_follow_the_disk_without_being_told(tmp_path: Path) -> None:
    helper = tmp_path / "helper.py"
    helper.write_text(HELPER.format(unit="km/h"))
    node = tmp_path / "node.py"
    node.write_text(NODE)
    client = Client()
    try:
        client.initialize(tmp_path)
        uri = client.open(node, NODE)
        codes = [[d["code"] for d in client.diagnostics()["diagnostics"]]]
        client.change(uri, 2, {"text": NODE + "\n"})  # a keystroke: the same
        codes.append([d["code"] for d in client.diagnostics()["diagnostics"]])
        helper.write_text(HELPER.format(unit="m/s"))  # in place, e.g. by git
        _later(helper)
        client.change(uri, 3, {"text": NODE})
        codes.append([d["code"] for d in client.diagnostics()["diagnostics"]])
        extra = tmp_path / "extra.py"
        extra.write_text(EXTRA)  # a new module beside the node
        _later(tmp_path)
        client.change(uri, 4, {"text": NODE + "\n"})
        codes.append([d["code"] for d in client.diagnostics()["diagnostics"]])
        extra.write_text(EXTRA.replace("deg/s", "rad/s"))
        client.notify("textDocument/didSave", {"textDocument": {"uri": extra.as_uri()}})
        client.change(uri, 5, {"text": NODE})
        codes.append([d["code"] for d in client.diagnostics()["diagnostics"]])
        assert client.stop() == 0
    finally:
        client.kill()
    assert codes == [["RF201"], ["RF201"], [], ["RF201"], []]


def kept_unless_moved_above(
    catalog: object, path: Path, project: object, root: Path
) -> bool:
    """The kept project comes back while nothing it stamped changed; it is built
    again only when a folder it stamped above `root` changed meanwhile (another
    process's files in `/tmp` or `/tmp/pytest-of-root`: a run of pytest in
    parallel), never for a change of ours."""
    _, kept, stamps = server._projects[id(catalog)]
    before = dict(stamps)
    if server._project(catalog, path) is project:  # type: ignore[arg-type]
        return kept is project
    moved = [f for f, stamp in before.items() if server._stamp(f) != stamp]
    return bool(moved) and all(not f.is_relative_to(root) for f in moved)


def test_a_kept_project_answers_as_a_new_one(tmp_path: Path) -> None:
    """The same diagnostics as `api.check_source` building its own project, for
    several documents sharing one catalog and so one kept project."""
    (tmp_path / "helper.py").write_text(HELPER.format(unit="km/h"))
    (tmp_path / "extra.py").write_text(EXTRA)
    session = server.Session()
    texts = {
        "node.py": NODE,
        "other.py": "from helper import SPEED\n\nx = SPEED\n",
        "third.py": NODE.replace("SPEED\n", "SPEED * 3.6\n", 1),
    }
    for _ in range(2):
        for name, text in texts.items():
            path = tmp_path / name
            catalog = server._catalog(session, path)
            project = server._project(catalog, path)
            kept = api.check_source(text, str(path), catalog=catalog, project=project)
            fresh = api.check_source(text, str(path), catalog=catalog)
            assert repr(kept) == repr(fresh)
            assert kept_unless_moved_above(catalog, path, project, tmp_path)


def test_hover_sees_an_imported_module_through_the_kept_summaries(
    tmp_path: Path,
) -> None:
    helper = tmp_path / "helper.py"
    helper.write_text(HELPER.format(unit="km/h"))
    node = tmp_path / "node.py"
    session = server.Session()
    session.documents.open(node.as_uri(), NODE, 1)
    line = NODE.splitlines().index("cmd.linear.x = SPEED")
    where = {
        "textDocument": {"uri": node.as_uri()},
        "position": {"line": line, "character": len("cmd.linear.x = ")},
    }

    def shown() -> str:
        found = server.hover(session, where)
        assert found is not None
        value: str = found["contents"]["value"]  # type: ignore[index]
        return value

    assert "km/h" in shown()
    helper.write_text(HELPER.format(unit="m/s"))
    _later(helper)
    assert "km/h" not in shown() and "m/s" in shown()


def _kept_and_fresh(session: server.Session, path: Path, text: str) -> list[str]:
    """The kept project's diagnostics for `text`, asserted equal to a new one's
    (checked as `server._publish` does: what the check read is stamped after)."""
    catalog = server._catalog(session, path)
    project = server._project(catalog, path)
    kept = api.check_source(text, str(path), catalog=catalog, project=project)
    server._record(project, server._projects[id(catalog)][2], path)
    fresh = api.check_source(text, str(path), catalog=catalog)
    assert repr(kept) == repr(fresh)
    return [d.code for d in kept]


def test_a_file_read_only_for_its_imports_drops_the_kept_project(
    tmp_path: Path,
) -> None:
    """`deep.py` is parsed only for its import edges (is `helper` reachable from
    `mid`?), never summarised: once it imports `helper`, `mid` is on a cycle
    with `helper` and is no longer consulted while `helper` is summarised."""
    (tmp_path / "helper.py").write_text(
        "from typing import Annotated\n\nimport mid\n\n"
        "def speed() -> Annotated[float, \"Unit('m/s')\"]:\n    return 1.0\n\n"
        "def turn(v: mid.Turn) -> None:\n    pass\n"
    )
    (tmp_path / "mid.py").write_text(
        "from typing import Annotated\n\nimport deep\n\n"
        "Turn = Annotated[float, \"Unit('rad/s')\"]\n"
    )
    deep = tmp_path / "deep.py"
    deep.write_text("X = 1\n")
    node = tmp_path / "node.py"
    text = (
        "from typing import Annotated\n\nfrom helper import turn\n\n"
        "SPEED: Annotated[float, \"Unit('m/s')\"] = 1.0\nturn(SPEED)\n"
    )
    session = server.Session()
    assert _kept_and_fresh(session, node, text) == ["RF201"]
    deep.write_text("import helper\n\nX = 1\n")
    _later(deep)
    assert _kept_and_fresh(session, node, text) == []
    catalog = server._catalog(session, node)
    project = server._project(catalog, node)
    assert deep in project.read_files()


def test_a_module_added_in_a_listed_folder_drops_the_kept_project(
    tmp_path: Path,
) -> None:
    """`pkgx/` (a folder without `__init__.py`: no file of it is summarised) was
    listed looking for `pkgx.mod` (absent): a module created there is seen, though
    no file the project read changed."""
    package = tmp_path / "pkgx"
    package.mkdir()
    node = tmp_path / "node.py"
    text = (
        NODE.replace("from helper import", "from pkgx.mod import")
        .replace("from extra import TURN\n", "")
        .replace("cmd.angular.z = TURN\n", "")
    )
    session = server.Session()
    assert _kept_and_fresh(session, node, text) == []
    catalog = server._catalog(session, node)
    assert str(package) in server._project(catalog, node).index.listed_folders()
    (package / "mod.py").write_text(HELPER.format(unit="km/h"))
    _later(package)
    assert _kept_and_fresh(session, node, text) == ["RF201"]


def test_a_document_that_proved_nothing_keeps_its_memo(tmp_path: Path) -> None:
    """The document's memo holds its analysis kept per item (`memo.units`) next to
    its proofs: a document with nothing to prove (most real nodes) keeps it across
    keystrokes too (an empty memo was dropped, so every edit made a new one and
    nothing was ever replayed)."""
    path = tmp_path / "node.py"
    text = "".join(
        [
            "from geometry_msgs.msg import Twist\n\n\nclass Node:\n",
            *(
                f"    def step_{i}(self, cmd: Twist):\n"
                f"        gain = {i + 1}.5\n"
                "        cmd.linear.x = gain\n\n"
                for i in range(6)
            ),
        ]
    )
    session = server.Session()
    uri = path.as_uri()
    server.did_open(session, {"textDocument": {"uri": uri, "text": text}})
    for version, gain in enumerate(("2.5", "2.5", "2.7"), start=1):
        edited = text.replace("gain = 2.5", f"gain = {gain}")
        change = {"textDocument": {"uri": uri, "version": version}}
        server.did_change(session, {**change, "contentChanges": [{"text": edited}]})
    memo = server._memo(uri)
    assert len(memo) == 0  # nothing proved: the memo is empty, so false
    assert memo.units is not None and memo.units.hits >= 5  # type: ignore[attr-defined]
