"""The predicates the shipped stubs write come parsed
(`annotations/stub_predicates.json`): as the parser parses them, and a file whose
only refinements are the stubs' imports no lark."""

from __future__ import annotations

from robotfix.annotations import parser as P


def test_the_stubs_predicates_come_parsed_as_the_parser_parses_them() -> None:
    shipped = P.shipped()
    assert "_ >= 0" in shipped, (
        "stub_predicates.json is stale: run python tools/build_package_data.py"
    )
    for text, node in shipped.items():
        assert P.spelt_node(node) == P.spelt_node(P._parse_uncached(text)), text


def test_a_file_whose_only_refinements_are_the_stubs_imports_no_lark() -> None:
    import subprocess
    import sys

    code = (
        "import sys, math\n"
        "from robotfix.api import check_source\n"
        "check_source('import math\\nimport time\\n"
        "d = math.sqrt(2.0)\\ntime.sleep(math.hypot(1.0, d))\\n', 'x.py')\n"
        "print('lark' in sys.modules)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == "False"
