"""`mech.index.lookup` and `parse_query` under hostile inputs (issue 24, item 7).

`lookup(None)` and `lookup(219)` raised AttributeError from ``query.strip()``. Now a
query that is not a string is a TypeError naming `query`, before any harvest; any string
either parses or is a ValueError naming `query` and showing it; `index` and `root` of the
wrong type are TypeErrors naming them.
"""

import pytest
from hypothesis import given, settings, strategies as st

from mech.index import Index, build_index, lookup, make_id, parse, parse_query

NOT_STRINGS = st.one_of(st.none(), st.integers(), st.floats(allow_nan=True), st.booleans(), st.binary(max_size=8),
                        st.lists(st.text(max_size=3), max_size=2), st.complex_numbers(),
                        st.dictionaries(st.text(max_size=2), st.integers(), max_size=1))


@pytest.fixture(scope="module")
def index():
    return build_index()


@settings(max_examples=200, deadline=None)
@given(query=NOT_STRINGS)
def test_query_not_a_string_is_a_type_error_naming_it(query):
    for call in (lambda: lookup(query), lambda: parse_query(query)):
        with pytest.raises(TypeError, match="`query`"):
            call()


@pytest.mark.parametrize("query", [None, 219, 2.19, b"2-19", ["2-19"]])
def test_reported_queries(query):
    with pytest.raises(TypeError, match=r"Expected `query` to be a string.*got " + repr(query).replace("[", r"\[")
                       .replace("]", r"\]").replace(".", r"\.")):
        lookup(query)


@settings(max_examples=300, deadline=None)
@given(query=st.text(max_size=12))
def test_any_text_parses_or_is_refused_by_name(query):
    try:
        keys = parse_query(query)
    except ValueError as exc:
        assert "`query`" in str(exc) and repr(query) in str(exc), str(exc)
    else:
        assert isinstance(keys, list) and all(isinstance(k, tuple) and len(k) == 2 for k in keys)


@pytest.mark.parametrize("query", ["", " ", "\t", "2-19x", "eq", "fig x"])
def test_empty_and_bad_text_refused_before_the_harvest(query):
    with pytest.raises(ValueError, match="`query`"):
        lookup(query, root="/nonexistent/folder")      # refused before the root is looked at


@settings(max_examples=30, deadline=None)
@given(query=st.from_regex(r"(eq |fig |ex |exercise |table )?2-[1-9][0-9]?", fullmatch=True))
def test_lookup_with_an_index_returns_entries(index, query):
    entries = lookup(query, index=index)
    assert isinstance(entries, list)


@pytest.mark.parametrize("bad", [5, "index", object()])
def test_index_of_the_wrong_type(bad):
    with pytest.raises(TypeError, match="`index`"):
        lookup("2-19", index=bad)


@pytest.mark.parametrize("bad", [5, b"/tmp", 1.5])
def test_root_of_the_wrong_type(bad):
    with pytest.raises(TypeError, match="`root`"):
        lookup("2-19", root=bad)


def test_index_is_the_public_class(index):
    assert isinstance(index, Index)


@settings(max_examples=60, deadline=None)
@given(text=NOT_STRINGS)
def test_parse_and_make_id_of_a_non_string_name_text(text):
    """`parse(None)` raised AttributeError, `make_id(None)` re's TypeError naming nothing."""
    for call in (lambda: parse(text), lambda: make_id(text)):
        with pytest.raises(TypeError, match="`text`"):
            call()
