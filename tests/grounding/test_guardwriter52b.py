"""Session 52 (12b): one list writer for the step guards and the refusals' guards."""

from __future__ import annotations

import ast
import re
from pathlib import Path
from typing import Any

from hltl.errors import GroundingError
from hltl.grounding import _refusal_guards, _step_guards, refusalguard, stepguard
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.stepguard import Entry

_OKAPI = re.compile(r"\bokapis? (?:is|are) asleep\b")


def _okapi_step(text: str, lexicon: Lexicon) -> str:
    """A step with a guard: it does something only where 'okapi' is said."""
    if "okapi" not in text:
        return text
    return text.replace("okapi", "zebra")


def _okapi_refusal(text: str, lexicon: Lexicon) -> None:
    """A refusal with a guard: it refuses only where its pattern matches."""
    m = _OKAPI.search(text)
    if m is None:
        return None
    raise GroundingError(m.group(0))


def _unguarded(text: str, lexicon: Lexicon) -> str:
    """No guard: its first statement may act on any text."""
    return text.strip()


def _read_back(source: str) -> dict[str, Any]:
    """The GUARDS of a generated list's source, as Python reads it."""
    names: dict[str, Any] = {}
    exec(compile(source, "<list>", "exec"), names)
    guards = names["GUARDS"]
    assert isinstance(guards, dict)
    return guards


def test_read_all_keys_each_read_entry_by_the_function_and_skips_the_unread() -> None:
    steps = stepguard.read_all((_okapi_step, _unguarded))
    assert list(steps) == [stepguard.key(_okapi_step)]
    assert steps[stepguard.key(_okapi_step)][1][0] == ("okapi",)
    # the reader is the list's: a refusal's is read with refusalguard's reader
    refusals = stepguard.read_all((_okapi_refusal, _unguarded), refusalguard.read_guard)
    assert list(refusals) == [stepguard.key(_okapi_refusal)]
    assert refusals == refusalguard.read_all((_okapi_refusal, _unguarded))
    # the step reader reads no guard of the refusal (its returns are not 'return text')
    assert stepguard.read_all((_okapi_refusal,)) == {}


def test_the_text_written_reads_back_as_the_entries_and_the_derivation() -> None:
    entries = stepguard.read_all((_okapi_step,))
    entries.update(stepguard.read_all((_okapi_refusal,), refusalguard.read_guard))
    source = stepguard.list_text("Some guards", "hltl.grounding.x", "d1g3st", entries)
    module = ast.parse(source)
    docstring = ast.get_docstring(module)
    assert docstring == "Some guards (made by python -m hltl.grounding.x --write)."
    assert "\n" not in docstring  # one line (tests/test_layers.py)
    assert _read_back(source) == {"derivation": "d1g3st", **entries}
    # sorted by name, whatever order the entries came in
    backwards = dict(reversed(list(entries.items())))
    assert stepguard.list_text("Some guards", "hltl.grounding.x", "d1g3st", backwards) == source


def test_the_committed_lists_are_what_the_writer_writes_of_their_entries() -> None:
    """Each committed list, its entries written again, reads back as itself, with the docstring
    its module's ``main`` writes."""
    for module, what, maker in (
        (_step_guards, "The normaliser's step guards", "hltl.grounding.stepguard"),
        (_refusal_guards, "The refusals' and checks' guards", "hltl.grounding.refusalguard"),
    ):
        known = dict(module.GUARDS)
        made = known.pop("derivation")
        assert isinstance(made, str)
        entries: dict[str, Entry] = {}
        for name, entry in known.items():
            assert isinstance(entry, tuple)
            entries[name] = entry
        assert len(entries) > 30
        source = stepguard.list_text(what, maker, made, entries)
        assert _read_back(source) == module.GUARDS
        assert ast.get_docstring(ast.parse(source)) == module.__doc__


def test_write_list_writes_the_file_and_counts_its_entries(tmp_path: Path) -> None:
    out = tmp_path / "_some_guards.py"
    fns = (_okapi_refusal, _unguarded)
    n = stepguard.write_list(out, fns, refusalguard.read_guard, "G", "hltl.grounding.x", "d")
    assert n == 1  # the unguarded function has no entry
    written = out.read_text(encoding="utf-8")
    expected = refusalguard.read_all(fns)
    assert written == stepguard.list_text("G", "hltl.grounding.x", "d", expected)
    assert _read_back(written) == {"derivation": "d", **expected}
