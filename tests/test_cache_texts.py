"""`cache._texts`, the batched check of a cache entry's strings, says what
`is_text` of each says (ASCII at once, anything else one by one)."""

from __future__ import annotations

from typing import Any

from hypothesis import given
from hypothesis import strategies as st

from robotfix.cache import _texts
from robotfix.disk_cache import is_text

VALUES = st.one_of(
    st.text(alphabet=st.characters(max_codepoint=127)),
    st.text(),  # lone surrogates too
    st.sampled_from(["\udcff", "caf\xe9", "\ud800x"]),
    st.integers(),
    st.none(),
    st.lists(st.text(), max_size=2),
)


@given(st.lists(VALUES, max_size=6), st.sampled_from(["strict", "surrogateescape"]))
def test_texts_is_is_text_of_each(values: list[Any], errors: str) -> None:
    assert _texts(values, errors) == all(is_text(v, errors) for v in values)
    keyed = {str(i): v for i, v in enumerate(values)}
    assert _texts(keyed.values(), errors) == all(is_text(v, errors) for v in values)
