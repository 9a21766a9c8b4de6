"""Bad input gets a clear diagnostic and never a traceback."""

from __future__ import annotations

from robotfix.source import SourceFile


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
