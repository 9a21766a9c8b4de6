"""Bad input gets a clear diagnostic and never a traceback."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from robotfix.source import LINE_BREAK, SourceFile, split_lines


def codes(data: bytes) -> list[str]:
    source = SourceFile.from_bytes("f.py", data)
    return [source.problem.code] if source.problem else []


def test_python2_is_recognised() -> None:
    assert codes(b'print "hello"\n') == ["RF002"]
    assert codes(b"try:\n    pass\nexcept ValueError, e:\n    pass\n") == ["RF002"]
    assert codes(b"x = 0777\n") == ["RF002"]


def test_plain_syntax_error() -> None:
    assert codes(b"def f(:\n") == ["RF001"]
    assert codes(b'"""Drive at `speed` m/s."""\ndef f(:\n    pass\n') == ["RF001"]
    assert codes(b"x = `1`\n") == ["RF002"]
    assert codes(b"x = 1\0\n") == ["RF001"]


def test_encodings() -> None:
    assert codes(b"\xff\xfe\xfa = 1\n") == ["RF003"]
    assert codes("\ufeffx = 'é'\r\ny = 2\r\n".encode()) == []
    assert codes(b"# -*- coding: latin-1 -*-\nx = '\xe9'\n") == []
    assert codes(b"") == []


def test_columns_are_characters() -> None:
    source = SourceFile.from_text("f.py", "é = 1; x = 2\n")
    assert source.char_col(1, len("é = 1; ".encode())) == len("é = 1; ")


PYTHON2_FORMS = {
    "tabs mixed with spaces": b"if True:\n        x = 1\n\ty = 2\n",
    "tuple parameters": b"def draw_str(dst, (x, y), s):\n    pass\n",
    "lambda tuple parameters": b"key = lambda (k, v): v\n",
    "print statement": b"import sys\nprint 'speed', 3\n",
    "backticks": b"label = `42`\n",
    "exec statement": b"exec 'x = 1' in {}\n",
    "ur string": b"pattern = ur'\\d+'\n",
    "octal literal": b"mode = 0755\n",
    "long literal": b"big = 10L\n",
    "not-equal operator": b"if 1 <> 2:\n    pass\n",
    "raise with a comma": b"raise ValueError, 'bad speed'\n",
    "except with a comma": b"try:\n    pass\nexcept IOError, e:\n    pass\n",
}


def test_every_python2_form_is_a_warning_not_an_error() -> None:
    found = {name: codes(data) for name, data in PYTHON2_FORMS.items()}
    assert found == {name: ["RF002"] for name in PYTHON2_FORMS}


def test_genuine_python3_syntax_errors_stay_errors() -> None:
    assert codes(b"if speed > 1\n    pass\n") == ["RF001"]
    assert codes(b"x = = 1\n") == ["RF001"]
    # 8 spaces + a tab is 16 columns in Python 2, like two tabs: valid Python 2
    assert codes(b"if True:\n\tif True:\n\t\tx = 1\n        \ty = 2\n") == ["RF002"]
    # a tab (8 columns) against 4 spaces is wrong in Python 2 too
    assert codes(b"if True:\n\tx = 1\n    y = 2\n") == ["RF001"]
    assert codes(b"def f(:\n\tpass\n        pass\n") == ["RF001"]
    assert codes(b"name = 'u' + `\n") == ["RF002"]  # a backtick is Python 2 only


def test_python_312_syntax_on_an_older_python_is_a_warning() -> None:
    import sys

    newer = [
        b"type Ports = dict[str, int]\n",
        b"def first[T](items: list[T]) -> T:\n    return items[0]\n",
        b"class Box[T]:\n    pass\n",
    ]
    expected = [] if sys.version_info >= (3, 12) else ["RF005"]
    assert [codes(data) for data in newer] == [expected] * 3
    assert codes(b"type = 3\nx = type +\n") == ["RF001"]  # `type`, a name


@given(st.text(alphabet="ab \n\r\f\v\x1c\x85\u2028", max_size=40))
def test_lines_are_split_as_ast_numbers_them(text: str) -> None:
    """`split_lines` splits a text without `\\r` by `str.split`: the same lines
    as the pattern of `\\r\\n`, `\\r` and `\\n` (a form feed, U+2028 and the other
    breaks of `str.splitlines` are no line break for `ast`)."""
    assert split_lines(text) == LINE_BREAK.split(text)
    assert SourceFile.from_text("f.py", text).lines == LINE_BREAK.split(text)
