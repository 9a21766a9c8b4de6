"""Quick fixes: the edits a unit message proposes (`Diagnostic.fixes`), and the code
actions `robotfix lsp` offers from them, each checked before it is offered; the
notes of a diagnostic as `relatedInformation` links (newuser2 §6, issue 24)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from robotfix import api
from robotfix.lsp import actions
from tests.lsp_client import Client

SOURCE = """import math
from typing import Annotated
from geometry_msgs.msg import Twist

speed: Annotated[float, "Unit('km/h')"] = 3
period_s: Annotated[float, "Unit('s')"] = 0.5
yaw: Annotated[float, "Unit('rad')"] = 0.1
deg: Annotated[float, "Unit('degree')"] = 30
cmd = Twist()
cmd.linear.x = speed + 1
wait: Annotated[float, "Unit('s')"] = period_s * 1000
cmd.angular.z = 0.5 * math.radians(yaw)
heading: Annotated[float, "Unit('rad')"] = math.degrees(yaw) / 2
turn: Annotated[float, "Unit('rad')"] = deg
"""

# line -> the fix's edited line, as the message words it
FIXED = {
    10: "cmd.linear.x = (speed + 1) / 3.6",
    11: "wait: Annotated[float, \"Unit('s')\"] = period_s",
    12: "cmd.angular.z = 0.5 * yaw",
    13: "heading: Annotated[float, \"Unit('rad')\"] = yaw / 2",
    14: "turn: Annotated[float, \"Unit('rad')\"] = math.radians(deg)",
}


def test_unit_messages_carry_the_edit_they_advise(tmp_path: Path) -> None:
    path = str(tmp_path / "node.py")
    found = [d for d in api.check_source(SOURCE, path) if d.code == "RF201"]
    assert sorted(d.span.line for d in found) == sorted(FIXED)
    for d in found:
        (fix,) = d.fixes
        edited = actions.applied(SOURCE, fix.edits).splitlines()[d.span.line - 1]
        assert edited == FIXED[d.span.line], d.message
        # applied, the diagnostic is gone and nothing else is reported
        after = api.check_source(actions.applied(SOURCE, fix.edits), path)
        assert {(a.code, a.span.line) for a in after} < {
            (b.code, b.span.line) for b in api.check_source(SOURCE, path)
        }


def test_no_fix_without_a_module_to_convert_with_or_a_round_factor(
    tmp_path: Path,
) -> None:
    text = SOURCE.replace("import math\n", "").replace(
        "cmd.angular.z = 0.5 * math.radians(yaw)\n", ""
    )
    text = text.replace("math.degrees(yaw) / 2", "deg / 2")
    path = str(tmp_path / "node.py")
    fixes = {d.span.line: d.fixes for d in api.check_source(text, path)}
    assert fixes[12] == ()  # `turn = deg`: no `math` to call radians() of
    assert fixes[11] == ()  # `deg / 2` into rad: 0.0349066*rad, no round factor


def _session(
    tmp_path: Path, text: str, ask: list[int], trigger: int = 1
) -> dict[str, Any]:
    client = Client()
    try:
        path = tmp_path / "node.py"
        path.write_text(text)
        caps = {"textDocument": {"publishDiagnostics": {"relatedInformation": True}}}
        initialized = client.initialize(tmp_path, caps)
        uri = client.open(path, text)
        opened = client.diagnostics()
        context = {"diagnostics": [], "triggerKind": trigger}
        answers = [client.code_action(uri, line, line, context) for line in ask]
        client.stop()
    finally:
        client.kill()
    return {"initialized": initialized, "opened": opened, "actions": answers}


def _edited(text: str, action: dict[str, Any]) -> str:
    from robotfix.lsp.documents import apply

    (edits,) = action["edit"]["changes"].values()
    for edit in sorted(
        edits,
        key=lambda e: (e["range"]["start"]["line"], e["range"]["start"]["character"]),
        reverse=True,
    ):
        text = apply(text, {"range": edit["range"], "text": edit["newText"]})
    return text


def test_code_actions_are_offered_only_once_checked(tmp_path: Path) -> None:
    # line 10 (0-based 9): the km/h store; line 5 (0-based 4) has no diagnostic but
    # `suggest` has nothing there either; a two-line file gets suggest's Unit()
    result = _session(tmp_path, SOURCE, [9, 4])
    capabilities = result["initialized"]["result"]["capabilities"]
    assert capabilities["codeActionProvider"]["codeActionKinds"] == [
        "quickfix",
        "refactor.rewrite",
    ]
    on_store, elsewhere = result["actions"]
    assert [a["title"] for a in on_store] == [
        "RobotFix: Convert with `/ 3.6`",
        "RobotFix: Silence RF201 on this line",
    ]
    assert all(a["kind"] == "quickfix" for a in on_store)
    assert on_store[0]["diagnostics"][0]["code"] == "RF201"
    silenced = _edited(SOURCE, on_store[1]).splitlines()[9]
    assert silenced == "cmd.linear.x = speed + 1  # robotfix: ignore[RF201]"
    assert elsewhere == []
    # the notes that have a place are links too (Neovim shows only the message)
    wait = next(
        d for d in result["opened"]["diagnostics"] if d["range"]["start"]["line"] == 10
    )
    (link,) = wait["relatedInformation"]
    assert link["message"] == "annotation of `wait` declared here"
    assert link["location"]["range"]["start"]["line"] == 10
    assert wait["message"].endswith("\nannotation of `wait` declared here")


def test_a_fix_that_would_not_check_clean_is_not_offered(tmp_path: Path) -> None:
    # the line already silences RF101, and ends in a `\` continuation: the
    # comment would break the parse, so only the conversion is offered
    text = SOURCE.replace(
        "cmd.linear.x = speed + 1\n", "cmd.linear.x = speed + \\\n    1\n"
    )
    result = _session(tmp_path, text, [9])
    (on_store,) = result["actions"]
    assert [a["title"] for a in on_store] == ["RobotFix: Convert with `/ 3.6`"]


def test_suggested_units_are_code_actions(tmp_path: Path) -> None:
    text = (
        "from geometry_msgs.msg import Twist\n"
        "\n"
        "def send(pub, distance_m, duration):\n"
        "    cmd = Twist()\n"
        "    v = distance_m\n"
        "    cmd.linear.x = v\n"
        "    pub.publish(cmd)\n"
    )
    result = _session(tmp_path, text, [4])
    (on_v,) = result["actions"]
    assert [a["title"] for a in on_v] == ["RobotFix: Annotate `v` with Unit('m/s')"]
    assert on_v[0]["kind"] == "refactor.rewrite"
    edited = _edited(text, on_v[0])
    assert "v: Annotated[float, \"Unit('m/s')\"] = distance_m" in edited
    assert edited.startswith("from typing import Annotated\n")
    # asked by the client at a cursor move: no second analysis for suggest
    assert _session(tmp_path, text, [4], trigger=2)["actions"] == [[]]


def test_a_request_checks_a_bounded_number_of_fixes_and_its_kinds(
    tmp_path: Path,
) -> None:
    """Over a whole file with many diagnostics, one request checks at most
    `MAX_TRIED` fixes (each is a check of the file); the next request goes on from
    the verdicts kept. A client asking only for refactorings gets no quick fix."""
    text = "from typing import Annotated\n" + "".join(
        f"v{i}: Annotated[float, \"Unit('m/s')\"] = 1.0\n"
        f"w{i}: Annotated[float, \"Unit('km/h')\"] = v{i}\n"
        for i in range(12)
    )
    path = tmp_path / "node.py"
    path.write_text(text)
    client = Client()
    try:
        client.initialize(tmp_path)
        uri = client.open(path, text)
        assert len(client.diagnostics()["diagnostics"]) == 12

        def ask(only: list[str] | None = None) -> list[dict[str, Any]]:
            context: dict[str, Any] = {"diagnostics": [], "triggerKind": 2}
            if only is not None:
                context["only"] = only
            return client.code_action(uri, 0, 30, context)

        first, second, refactors = ask(), ask(), ask(["refactor"])
        client.stop()
    finally:
        client.kill()
    assert len(first) == actions.MAX_TRIED  # 8 diagnostics, 2 fixes each
    assert len(second) == 24  # the 16 kept, and the 8 checked now
    assert refactors == []
    assert {a["title"] for a in second} == {
        "RobotFix: Convert with `* 3.6`",
        "RobotFix: Silence RF201 on this line",
    }
