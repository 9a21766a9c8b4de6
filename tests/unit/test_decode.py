"""`source._decode`'s fast path (no BOM, no `coding` on the first two lines: the
text is `data.decode()`) gives what `tokenize.detect_encoding` and its codec give,
text or error, for every file of the cases and for the forms PEP 263 names."""

from __future__ import annotations

import io
import tokenize
from pathlib import Path

import pytest

from robotfix import source

CASES = Path(__file__).resolve().parent.parent / "cases"

FORMS = [
    b"",
    b"x = 1",
    b"x = 1\n",
    b"\xef\xbb\xbfx = 1\n",  # BOM
    b"\xef\xbb\xbf# -*- coding: latin-1 -*-\nx = 1\n",  # BOM and another cookie
    b"# -*- coding: latin-1 -*-\nx = '\xe9'\n",
    b"#!/usr/bin/env python\n# coding=latin-1\nx = '\xe9'\n",
    b"\n# vim: set fileencoding=cp1252 :\nx = '\x80'\n",
    b"x = 1\n# coding: latin-1\n",  # line 2 after code: read (the first is not blank)
    b"x = 1\ny = 2\n# coding: latin-1\nz = '\xe9'\n",  # line 3: ignored
    b"s = 'coding is fun'\nx = '\xc3\xa9'\n",  # the word, no cookie
    b"# coding: no-such-codec\nx = 1\n",
    b"x = '\xe9'\n",  # not UTF-8, no cookie
    b"x = 1\ny = '\xe9'\n",  # not UTF-8 on line 2
    b"x = 1\ny = 2\nz = '\xff'\n",  # not UTF-8 past the lines tokenize reads
    b"# coding: utf-8\r# old Mac line ends\rx = 1\r",
    b"x = '\xc3\xa9'\r\n# coding: latin-1\r\n",
    b"\xef\xbb\xbf# coding: latin-1\n",  # BOM against a cookie: an error
    b"x = 1\x00\n",
]


def _slow(data: bytes) -> str:
    encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
    text = data.decode(encoding)
    return text[1:] if text.startswith("\ufeff") else text


def _outcome(decode: object, data: bytes) -> tuple[str, str]:
    try:
        return ("text", decode(data))  # type: ignore[operator]
    except (SyntaxError, UnicodeDecodeError, LookupError) as err:
        return (type(err).__name__, str(err))


@pytest.mark.parametrize("data", FORMS)
def test_a_form_decodes_as_tokenize_decodes_it(data: bytes) -> None:
    assert _outcome(source._decode, data) == _outcome(_slow, data)


def test_every_case_decodes_as_tokenize_decodes_it() -> None:
    files = sorted(p for p in CASES.rglob("*.py") if p.is_file())
    assert len(files) > 100
    for path in files:
        data = path.read_bytes()
        assert _outcome(source._decode, data) == _outcome(_slow, data), path


def test_a_plain_file_is_not_read_by_tokenize(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(readline: object) -> None:
        raise AssertionError("tokenize.detect_encoding asked")

    monkeypatch.setattr(tokenize, "detect_encoding", refuse)
    text = source._decode(b"import rclpy\nx = '\xc3\xa9'\n")
    assert text == "import rclpy\nx = '\xe9'\n"
