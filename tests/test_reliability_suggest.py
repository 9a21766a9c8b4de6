"""`robotfix suggest` never damages a file: the reliability report's F1-F4, C7, K5
and H6 (for suggest), and issue 11's item 6, each from its reproducer."""

from __future__ import annotations

import ast
import os
import re
import stat
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from robotfix import api
from robotfix.ros.catalog import MsgCatalog
from robotfix.suggest import UnsafeEditError, _whole_name, annotate, run_suggest
from tests.test_cli import run

BODY = (
    "from geometry_msgs.msg import Twist\n"
    "\n"
    "cmd = Twist()\n"
    "speed = 0.5\n"
    "cmd.linear.x = speed\n"
)
ANNOTATED = "speed: Annotated[float, \"Unit('m/s')\"] = 0.5"
IMPORT = "from typing import Annotated"


@pytest.fixture(scope="module")
def catalog() -> MsgCatalog:
    return MsgCatalog([])


def lines_of(text: str) -> list[str]:
    return re.split(r"\r\n|\r|\n", text)


def suggest(*paths: Path, apply: bool = True) -> int:
    return run_suggest(list(paths), [], apply)


# -- where the import goes (F1, K5) ---------------------------------------------


def test_shebang_stays_on_line_1(catalog: MsgCatalog) -> None:
    changed = annotate("#!/usr/bin/env python3\n" + BODY, "node.py", catalog)
    assert lines_of(changed)[:3] == [
        "#!/usr/bin/env python3",
        IMPORT,
        "from geometry_msgs.msg import Twist",
    ]
    assert ANNOTATED in changed


def test_coding_cookie_and_licence_header_stay_above_the_import(
    catalog: MsgCatalog,
) -> None:
    header = (
        "#!/usr/bin/env python\n"
        "# -*- coding: utf-8 -*-\n"
        "# Copyright 2020 Someone\n"
        "# Licensed under the BSD licence\n"
        "\n"
    )
    changed = annotate(header + BODY, "node.py", catalog)
    assert changed.startswith(header + IMPORT + "\n" + BODY.splitlines()[0])


def test_import_after_docstring_and_future_imports(catalog: MsgCatalog) -> None:
    head = '#!/usr/bin/env python3\n"""Drive.\n\nMore."""\n# note\n'
    future = "from __future__ import annotations\n"
    changed = annotate(head + future + BODY, "node.py", catalog)
    assert changed.startswith(head + future + IMPORT + "\n")


def test_backslash_after_the_docstring(catalog: MsgCatalog) -> None:
    text = '"""Doc.""" \\\n\n' + BODY
    changed = annotate(text, "node.py", catalog)
    ast.parse(changed)
    assert changed.startswith('"""Doc.""" \\\n\n' + IMPORT + "\n")
    assert ANNOTATED in changed


def test_docstring_sharing_a_logical_line(catalog: MsgCatalog) -> None:
    text = '"""Doc."""; limit = (\n    3)\n' + BODY
    changed = annotate(text, "node.py", catalog)
    assert lines_of(changed)[2] == IMPORT
    ast.parse(changed)


# -- lines and names (F2) -------------------------------------------------------


def test_form_feed_does_not_shift_lines_and_names_match_whole(
    catalog: MsgCatalog,
) -> None:
    text = (
        '"""Drive node."""\n'
        "from typing import Annotated\n"
        "from geometry_msgs.msg import Twist\n"
        "\x0c\n"
        "\n"
        "def drive(pub):\n"
        "    speed_limit = 3\n"
        "    speed = 0.5\n"
        "    cmd = Twist()\n"
        "    cmd.linear.x = speed\n"
        "    pub.publish(cmd)\n"
    )
    changed = annotate(text, "node.py", catalog)
    ast.parse(changed)
    assert "    speed_limit = 3\n" in changed
    assert "    " + ANNOTATED + "\n" in changed


def test_form_feed_in_the_docstring_leaves_it_alone(catalog: MsgCatalog) -> None:
    doc = '"""Teleop node.\x0c\n\nSee the manual."""\n'
    changed = annotate(doc + BODY, "node.py", catalog)
    assert changed.startswith(doc + IMPORT + "\n")
    assert (
        ast.get_docstring(ast.parse(changed)) == "Teleop node.\x0c\n\nSee the manual."
    )
    assert ANNOTATED in changed


@pytest.mark.parametrize("separator", ["\x0c", "\x1c", "\x85", "\u2028", "\u2029"])
def test_other_splitlines_breaks_are_not_line_breaks(
    catalog: MsgCatalog, separator: str
) -> None:
    text = f"# a comment {separator} inside\n" + BODY
    changed = annotate(text, "node.py", catalog)
    assert lines_of(changed)[:2] == [f"# a comment {separator} inside", IMPORT]
    assert ANNOTATED in changed


def test_a_name_is_matched_whole() -> None:
    assert not _whole_name("speed_limit = 3", 0, 5, "speed")
    assert not _whole_name("max_speed = 3", 4, 9, "speed")
    assert _whole_name("speed = 3", 0, 5, "speed")
    assert _whole_name("a = 1; speed=3", 7, 12, "speed")


# -- the edit is checked before anything is shown or written (F2) --------------


def _misplaced(monkeypatch: pytest.MonkeyPatch, line: int, col: int) -> None:
    """A suggestion that points where an annotation does not belong."""
    wrong = [api.Suggestion(line, col, "x", "m", "float")]
    monkeypatch.setattr(api, "unit_suggestions", lambda *args: wrong)


def test_an_edit_that_does_not_parse_is_not_written(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text("f(x=1)\n")
    _misplaced(monkeypatch, 1, 2)
    with pytest.raises(UnsafeEditError, match="would not parse"):
        annotate("f(x=1)\n", "node.py", MsgCatalog([]))
    assert suggest(node) == 2
    assert node.read_text() == "f(x=1)\n"
    out, err = capsys.readouterr()
    assert out == "No suggestions in 1 file.\n"
    assert err.startswith(
        f"robotfix: {node}: not annotated: the edited file would not parse ("
    )
    assert len(err.splitlines()) == 1


def test_an_edit_that_changes_a_string_is_not_written(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    _misplaced(monkeypatch, 1, 7)
    with pytest.raises(UnsafeEditError, match="more than the annotations"):
        annotate('s = """x = 1"""\n', "node.py", MsgCatalog([]))


# -- line endings and encodings (K5, issue 11 item 6) ---------------------------


@pytest.mark.parametrize("newline", ["\r\n", "\r"])
def test_line_endings_are_kept(tmp_path: Path, newline: str) -> None:
    node = tmp_path / "node.py"
    node.write_bytes(
        ("#!/usr/bin/env python3\n" + BODY).replace("\n", newline).encode()
    )
    assert suggest(node) == 0
    data = node.read_bytes().decode()
    assert re.findall(r"\r\n|\r|\n", data) == [newline] * 7
    assert data.split(newline)[:2] == ["#!/usr/bin/env python3", IMPORT]


def test_a_bom_file_is_annotated_and_keeps_its_bom(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_bytes(b"\xef\xbb\xbf" + BODY.encode())
    assert suggest(node) == 0
    data = node.read_bytes()
    assert data.startswith(b"\xef\xbb\xbf" + IMPORT.encode() + b"\n")
    assert ANNOTATED.encode() in data


def test_a_latin1_file_keeps_its_encoding(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    header = "# -*- coding: latin-1 -*-\n# café\n"
    node.write_bytes((header + BODY).encode("latin-1"))
    assert suggest(node) == 0
    data = node.read_bytes()
    assert data.startswith(header.encode("latin-1") + IMPORT.encode() + b"\n")
    assert ANNOTATED in data.decode("latin-1")


# -- writing (F3, F4) -----------------------------------------------------------


def test_a_failed_write_leaves_the_file_intact(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)

    def full(fd: int) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "fsync", full)
    assert suggest(node) == 2
    assert node.read_text() == BODY
    assert sorted(p.name for p in tmp_path.iterdir()) == ["node.py"]  # no temp file
    err = capsys.readouterr().err
    assert err == (
        f"robotfix: {node}: cannot write: No space left on device; left as it was\n"
    )


def test_the_file_mode_is_kept(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text("#!/usr/bin/env python3\n" + BODY)
    node.chmod(0o750)
    assert suggest(node) == 0
    assert stat.S_IMODE(node.stat().st_mode) == 0o750


def test_a_link_out_of_the_tree_is_never_written_through(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    tree, elsewhere = tmp_path / "tree", tmp_path / "elsewhere"
    tree.mkdir()
    elsewhere.mkdir()
    (elsewhere / "theirs.py").write_text(BODY)
    (tree / "link.py").symlink_to("../elsewhere/theirs.py")
    (tree / "mine.py").write_text(BODY)
    assert suggest(tree) == 2
    assert (elsewhere / "theirs.py").read_text() == BODY
    assert (tree / "link.py").is_symlink()
    assert ANNOTATED in (tree / "mine.py").read_text()
    assert "outside the checked paths; not written" in capsys.readouterr().err


def test_a_link_inside_the_tree_is_written_once_at_its_target(tmp_path: Path) -> None:
    (tmp_path / "real.py").write_text(BODY)
    (tmp_path / "alias.py").symlink_to("real.py")
    assert suggest(tmp_path) == 0
    assert (tmp_path / "alias.py").is_symlink()
    assert (tmp_path / "real.py").read_text().count(IMPORT) == 1


def test_a_file_changed_while_it_was_read_is_not_written(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)
    real = annotate

    def edited_meanwhile(
        text: str, path: str, catalog: MsgCatalog, *seen: object
    ) -> str:
        node.write_text(BODY + "# edited\n")
        return real(text, path, catalog, *seen)

    monkeypatch.setattr("robotfix.suggest.annotate", edited_meanwhile)
    assert suggest(node) == 2
    assert node.read_text() == BODY + "# edited\n"
    assert "changed while it was read; not written" in capsys.readouterr().err


# -- one bad file never stops the run (C7, H6) ----------------------------------


@pytest.mark.skipif(sys.platform == "win32", reason="FIFOs and /dev/zero")
def test_bad_files_get_a_line_each_and_the_others_are_written(tmp_path: Path) -> None:
    tree = tmp_path / "tree"
    tree.mkdir()
    (tree / "a_dangling.py").symlink_to("nowhere.py")
    (tree / "b_readonly.py").write_text(BODY)
    (tree / "b_readonly.py").chmod(0o444)
    os.mkfifo(tree / "fifo")
    (tree / "c_fifo.py").symlink_to("fifo")
    (tree / "d_zero.py").symlink_to("/dev/zero")
    (tree / "e_folder.py").symlink_to(tmp_path)
    (tree / "f_good.py").write_text(BODY)
    os.mkfifo(tmp_path / "named.py")
    result = run("suggest", "tree", "named.py", "--apply", cwd=tmp_path)
    assert result.returncode == 2
    outside = "outside the checked paths; not written"
    link = "not checked: a symlink to"
    assert result.stderr.splitlines() == [  # links leaving the paths are named first
        f"robotfix: tree/d_zero.py: {link} `/dev/zero`, {outside}",
        f"robotfix: tree/e_folder.py: {link} `{tmp_path}`, {outside}",
        "robotfix: named.py: cannot read: not a regular file; skipped",
        "robotfix: tree/a_dangling.py: cannot read: No such file or directory; skipped",
        "robotfix: tree/b_readonly.py: read-only; not written",
        "robotfix: tree/c_fifo.py: cannot read: not a regular file; skipped",
    ]
    assert (tree / "b_readonly.py").read_text() == BODY
    assert ANNOTATED in (tree / "f_good.py").read_text()
    assert "+++ b/tree/f_good.py" in result.stdout


@pytest.mark.skipif(
    sys.platform == "win32" or os.geteuid() == 0, reason="root reads anything"
)
def test_an_unreadable_file_is_skipped(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "a.py").write_text(BODY)
    (tmp_path / "a.py").chmod(0)
    (tmp_path / "b.py").write_text(BODY)
    assert suggest(tmp_path) == 2
    assert ANNOTATED in (tmp_path / "b.py").read_text()
    assert "a.py: cannot read: Permission denied; skipped" in capsys.readouterr().err


def test_an_internal_error_in_one_file_does_not_stop_the_run(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "a.py").write_text(BODY)
    (tmp_path / "b.py").write_text(BODY)
    real = api.unit_suggestions

    def broken(
        text: str, path: str, catalog: MsgCatalog, *seen: object
    ) -> list[api.Suggestion]:
        if path.endswith("a.py"):
            raise OverflowError("int too large to convert to float")
        return real(text, path, catalog, *seen)

    monkeypatch.setattr(api, "unit_suggestions", broken)
    assert suggest(tmp_path) == 2
    assert ANNOTATED in (tmp_path / "b.py").read_text()
    assert (
        "internal error while suggesting for "
        f"{tmp_path / 'a.py'}: OverflowError: int too large to convert to float"
    ) in capsys.readouterr().err


def test_a_missing_path_does_not_stop_the_others(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "b.py").write_text(BODY)
    assert suggest(tmp_path / "gone.py", tmp_path / "b.py") == 2
    assert ANNOTATED in (tmp_path / "b.py").read_text()
    assert "gone.py: no such file or directory" in capsys.readouterr().err


def test_no_suggestions_is_said(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "a.py").write_text("x = 1\n")
    (tmp_path / "b.py").write_text("y = 2\n")
    assert suggest(tmp_path, apply=False) == 0
    assert capsys.readouterr() == ("No suggestions in 2 files.\n", "")


# -- generated layouts ----------------------------------------------------------

HEADERS = st.lists(
    st.sampled_from(
        [
            "# Copyright 2024 Someone\n",
            "# SPDX-License-Identifier: BSD-3-Clause\n",
            "\n",
            "\x0c\n",
            "# a form feed \x0c and a line separator \u2028 in a comment\n",
        ]
    ),
    max_size=4,
)
DOCSTRINGS = st.sampled_from(
    [
        "",
        '"""Node."""\n',
        '"""Node.\x0c\n\nMore."""\n',
        "'''Node.''' \\\n\n",
        '"Doc"; n = (\n 1)\n',
    ]
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    shebang=st.booleans(),
    cookie=st.booleans(),
    header=HEADERS,
    docstring=DOCSTRINGS,
    future=st.booleans(),
    newline=st.sampled_from(["\n", "\r\n", "\r"]),
)
def test_generated_layouts_keep_their_head_and_breaks(
    catalog: MsgCatalog,
    shebang: bool,
    cookie: bool,
    header: list[str],
    docstring: str,
    future: bool,
    newline: str,
) -> None:
    assume(not (future and ";" in docstring))  # __future__ must come first
    head = ("#!/usr/bin/env python3\n" if shebang else "") + (
        "# -*- coding: utf-8 -*-\n" if cookie else ""
    )
    text = head + "".join(header) + docstring
    text += "from __future__ import annotations\n" if future else ""
    original = (text + BODY).replace("\n", newline)
    changed = annotate(original, "node.py", catalog)
    ast.parse(changed)
    before, after = lines_of(original), lines_of(changed)
    # everything up to the import is kept, on its lines; one line is inserted
    at = after.index(IMPORT)
    assert after[:at] == before[:at]
    assert len(after) == len(before) + 1
    assert at >= len(lines_of(text.replace("\n", newline))) - 1
    assert re.findall(r"\r\n|\r|\n", changed) == [newline] * (len(after) - 1)
    assert ANNOTATED in changed


# -- reliability2: owner, hard links, rebound names, concurrent edits (N1-N3) ---

ROOT_ONLY = pytest.mark.skipif(
    sys.platform == "win32" or os.geteuid() != 0, reason="giving a file away: root"
)


@ROOT_ONLY
def test_apply_as_root_keeps_owner_group_mode_and_xattrs(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)
    os.chown(node, 1234, 1234)
    node.chmod(0o640)
    try:
        os.setxattr(node, "user.origin", b"vendored")
    except OSError:
        pytest.skip("no user extended attributes on this file system")
    assert suggest(node) == 0
    info = node.stat()
    assert ANNOTATED in node.read_text()
    assert (info.st_uid, info.st_gid, stat.S_IMODE(info.st_mode)) == (1234, 1234, 0o640)
    assert os.getxattr(node, "user.origin") == b"vendored"


def test_a_hard_linked_file_is_not_split(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "tree").mkdir()
    node = tmp_path / "tree" / "node.py"
    node.write_text(BODY)
    os.link(node, tmp_path / "other_link.py")
    inode = node.stat().st_ino
    assert suggest(tmp_path / "tree") == 2
    assert node.read_text() == BODY and node.stat().st_ino == inode
    assert (tmp_path / "other_link.py").stat().st_ino == inode
    assert capsys.readouterr().err == (
        f"robotfix: {node}: has 2 hard links, which a rewrite would split; "
        "not written\n"
    )


@ROOT_ONLY
def test_an_owner_that_cannot_be_kept_is_not_given_away(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)
    os.chown(node, 1234, 1234)

    def not_allowed(fd: int, uid: int, gid: int) -> None:
        raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(os, "fchown", not_allowed)  # as a user other than root
    assert suggest(node) == 2
    assert node.read_text() == BODY and node.stat().st_uid == 1234
    assert "owned by uid 1234, gid 1234" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["node.py"]


REBOUND = [
    "Annotated = 5\n",
    "def Annotated():\n    pass\n",
    "import numpy as Annotated\n",
    "from mylib import Annotated\n",
    "class Holder:\n    Annotated = 1\n",
    "def rebind():\n    global Annotated\n    Annotated = 1\n",
    "for Annotated in range(3):\n    pass\n",
]


@pytest.mark.parametrize("binding", REBOUND)
def test_a_module_binding_annotated_gets_typing_annotated(
    catalog: MsgCatalog, binding: str
) -> None:
    changed = annotate(binding + BODY, "node.py", catalog)
    assert changed == "import typing\n" + binding + BODY.replace(
        "speed = 0.5", "speed: typing.Annotated[float, \"Unit('m/s')\"] = 0.5"
    )


def test_the_check_of_the_edit_catches_a_rebound_name_on_its_own(
    monkeypatch: pytest.MonkeyPatch, catalog: MsgCatalog
) -> None:
    # the check does not trust how `annotate` chose its spelling
    monkeypatch.setattr("robotfix.suggest._spelling", lambda names: "Annotated")
    with pytest.raises(UnsafeEditError, match="`Annotated` is bound in this module"):
        annotate("Annotated = 5\n" + BODY, "node.py", catalog)


def test_typing_annotated_uses_an_import_of_typing_above_it(
    catalog: MsgCatalog,
) -> None:
    text = "import typing\nAnnotated = 5\n" + BODY
    assert annotate(text, "node.py", catalog) == text.replace(
        "speed = 0.5", "speed: typing.Annotated[float, \"Unit('m/s')\"] = 0.5"
    )


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        (
            "Annotated = 5\nimport os as typing\n" + BODY,
            "both `Annotated` and `typing`",
        ),
        ("float = int\n" + BODY, "`float` is bound in this module to something else"),
    ],
)
def test_a_module_whose_names_cannot_be_written_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, reason: str
) -> None:
    node = tmp_path / "node.py"
    node.write_text(text)
    assert suggest(node) == 2
    assert node.read_text() == text
    err = capsys.readouterr().err
    assert err.startswith(f"robotfix: {node}: not annotated: ") and reason in err


def test_an_import_below_the_annotation_is_not_relied_on(catalog: MsgCatalog) -> None:
    # module-level annotations are evaluated at import: `Annotated` must be bound
    # above the first one, so the edit adds its own import
    text = BODY + IMPORT + "\n"
    assert annotate(text, "node.py", catalog) == IMPORT + "\n" + text.replace(
        "speed = 0.5", ANNOTATED
    )


def test_typing_extensions_annotated_is_used_as_it_is(catalog: MsgCatalog) -> None:
    text = "from typing_extensions import Annotated\n" + BODY
    assert annotate(text, "node.py", catalog) == text.replace("speed = 0.5", ANNOTATED)


def _append_during(
    monkeypatch: pytest.MonkeyPatch, name: str, node: Path, times: int = 1
) -> None:
    """`os.<name>` appends a line to `node` the first `times` times it is called,
    then does what it does: a writer landing at that moment of the write."""
    real = getattr(os, name)
    calls = []

    def hooked(*args: object) -> object:
        if len(calls) < times:
            calls.append(args)
            with open(node, "a") as out:
                out.write(f"# appended meanwhile {len(calls)}\n")
        return real(*args)

    monkeypatch.setattr(os, name, hooked)


def test_an_append_after_the_first_check_is_kept(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)
    _append_during(monkeypatch, "fsync", node)  # the temporary file is being written
    assert suggest(node) == 2
    assert node.read_text() == BODY + "# appended meanwhile 1\n"
    assert capsys.readouterr().err == (
        f"robotfix: {node}: changed while it was read; not written\n"
    )
    assert sorted(p.name for p in tmp_path.iterdir()) == ["node.py"]


def test_an_append_that_reaches_the_replaced_file_is_put_back(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)
    node.chmod(0o640)
    _append_during(monkeypatch, "replace", node)  # after the last check: the rename
    assert suggest(node) == 2
    assert node.read_text() == BODY + "# appended meanwhile 1\n"
    assert stat.S_IMODE(node.stat().st_mode) == 0o640
    assert capsys.readouterr().err == (
        f"robotfix: {node}: another program wrote to it during the rewrite; "
        "put back with that write; not written\n"
    )


def test_a_write_that_cannot_be_put_back_is_said(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(BODY)
    _append_during(monkeypatch, "replace", node, times=2)  # the rewrite and the undo
    assert suggest(node) == 2
    assert node.read_text() == BODY + "# appended meanwhile 1\n"
    assert capsys.readouterr().err == (
        f"robotfix: {node}: another program wrote to it during the rewrite, and one "
        "of its writes is lost\n"
    )
