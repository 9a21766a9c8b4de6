"""A real client session with `robotfix lsp` over stdio: diagnostics, hover, and a
server that survives syntax errors and Python 2 files."""

from __future__ import annotations

from pathlib import Path
from typing import Any
from urllib.parse import urlparse
from urllib.request import url2pathname

from tests.lsp_client import Client

SOURCE = """from typing import Annotated
from geometry_msgs.msg import Twist

timeout: Annotated[int, "_ < 200"] = 200
speed: Annotated[float, "Unit('km/h')"] = 3
cmd = Twist()
cmd.linear.x = speed
"""


def session(tmp_path: Path) -> dict[str, Any]:
    client = Client()
    try:
        path = tmp_path / "node.py"
        path.write_text(SOURCE)
        initialized = client.initialize(tmp_path)
        uri = client.open(path, SOURCE)
        opened = client.diagnostics()
        hover = client.hover(uri, 6, 11)
        broken = SOURCE + "def f(:\n"
        client.change(uri, 2, {"text": broken})
        after_syntax_error = client.diagnostics()
        client.change(uri, 3, {"text": 'print "py2"\n'})
        after_python2 = client.diagnostics()
        client.notify("textDocument/didSave", {"textDocument": {"uri": uri}})
        code = client.stop()
    finally:
        client.kill()
    return {
        "initialized": initialized,
        "opened": opened,
        "hover": hover,
        "syntax": after_syntax_error,
        "python2": after_python2,
        "exit": code,
    }


def test_language_server_session(tmp_path: Path) -> None:
    result = session(tmp_path)
    capabilities = result["initialized"]["result"]["capabilities"]
    assert capabilities["textDocumentSync"]["change"] == 2  # incremental
    assert capabilities["hoverProvider"] is True
    opened = result["opened"]
    found = sorted(
        (
            d["code"],
            d["range"]["start"]["line"],
            d["range"]["start"]["character"],
            d["range"]["end"]["line"],
        )
        for d in opened["diagnostics"]
    )
    assert found == [("RF101", 3, 0, 3), ("RF201", 6, 0, 6)]
    rf201 = next(d for d in opened["diagnostics"] if d["code"] == "RF201")
    assert rf201["source"] == "robotfix" and "divide by 3.6" in rf201["message"]
    # the link opens the rule's page installed beside the checker (no web site)
    href = rf201["codeDescription"]["href"]
    assert href.startswith("file:///") and href.endswith("/RF201.md")
    page = Path(url2pathname(urlparse(href).path))
    assert page.read_text(encoding="utf-8").startswith("# RF201 `unit-mismatch`")
    assert rf201["severity"] == 1
    hover = result["hover"]["result"]
    assert hover["contents"]["kind"] == "markdown"
    assert "**linear.x** of `geometry_msgs/Twist`" in hover["contents"]["value"]
    assert "m/s" in hover["contents"]["value"]
    assert [d["code"] for d in result["syntax"]["diagnostics"]] == ["RF001"]
    assert [d["code"] for d in result["python2"]["diagnostics"]] == ["RF002"]
    assert result["exit"] == 0
