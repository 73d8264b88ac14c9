"""Session 51 (12b): the refusals and checks asked of every text, indexed by their words
(refusalguard.py): a guard read from a refusal's source, and no refusal left unasked that would
have refused."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _refusal_guards, offline, refusalguard
from hltl.grounding._rewrites42r import maybe_it_was42r
from hltl.grounding.lexicon import Lexicon

_ZEBRA = re.compile(r"\bthe (?:zebra|okapi)s? (?:is|are) (?:asleep|away)\b", re.I)


def _zebra_word(text: str, lexicon: Lexicon) -> None:
    """A refusal of the usual shape: a word test, then the rule."""
    low = text.lower()
    if "zebra" not in low and "okapi" not in low:
        return
    raise GroundingError(f"{text!r}: zebra")


def _zebra_pattern(text: str, lexicon: Lexicon) -> None:
    """A refusal that searches a pattern and returns where it finds nothing."""
    m = _ZEBRA.search(text)
    if m is None:
        return None
    raise GroundingError(f"{m.group(0)!r}")


def _zebra_loop(text: str, lexicon: Lexicon) -> None:
    """A refusal that loops over a pattern's matches and ends without a return."""
    for m in _ZEBRA.finditer(text):
        if len(m.group(0)) > 3:
            raise GroundingError(f"{m.group(0)!r}")


def _zebra_first(text: str, lexicon: Lexicon) -> None:
    """A refusal whose first statement may refuse any text: no guard."""
    if len(text) > 400:
        raise GroundingError("too long")
    if "zebra" not in text:
        return


def _zebra_helper(text: str, lexicon: Lexicon) -> None:
    """A refusal that asks a helper of its own first: no guard."""
    if not lexicon.named.get(text):
        return
    raise GroundingError("named")


@pytest.fixture
def fresh(monkeypatch: pytest.MonkeyPatch) -> None:
    """The list read again from the refusals' source as they are now (the committed list may
    be older than a rule merged since: its changed functions are then asked always, until it is
    remade), with no guards kept from before."""
    known: dict[str, object] = {"derivation": refusalguard.derivation()}
    known.update(refusalguard.read_all(refusalguard.all_refusals()))
    monkeypatch.setattr(_refusal_guards, "GUARDS", known)
    monkeypatch.setattr(refusalguard, "_GUARDED", {})


def test_guard_read_from_a_word_test() -> None:
    entry = refusalguard.read_guard(_zebra_word)
    assert entry is not None
    assert entry[1] == ((), ("okapi", "zebra"), False)


def test_guard_read_from_a_pattern_and_a_loop() -> None:
    for fn in (_zebra_pattern, _zebra_loop):
        entry = refusalguard.read_guard(fn)
        assert entry is not None, fn.__name__
        plain, folded, patterned = entry[1]
        assert patterned
        assert {"zebra", "okapi"} <= set(folded) | set(plain), entry[1]
        assert ("_ZEBRA", ("pattern", _ZEBRA.pattern, int(_ZEBRA.flags))) in entry[2]


def test_no_guard_where_the_first_statements_may_refuse() -> None:
    assert refusalguard.read_guard(_zebra_first) is None
    assert refusalguard.read_guard(_zebra_helper) is None


def test_a_step_reader_reads_no_refusal() -> None:
    # the step guards' reader alone reads no guard of a refusal (it ends with 'return', not
    # with its text): the bare return is what refusalguard reads as 'nothing done'
    from hltl.grounding import stepguard

    assert stepguard.read_guard(_zebra_word) is None
    assert refusalguard.read_guard(_zebra_word) is not None


def test_asked_by_the_words() -> None:
    fns = (_zebra_word, _zebra_first)
    known = {"derivation": refusalguard.derivation()}
    entry = refusalguard.read_guard(_zebra_word)
    assert entry is not None
    known[f"{__name__}:_zebra_word"] = entry
    rules = refusalguard.guards(fns, known)
    assert rules[0] == entry[1] and rules[1] is None
    # a list made another way: no guard used
    assert refusalguard.guards(fns, {**known, "derivation": "x"}) == (None, None)


@pytest.mark.usefixtures("fresh")
def test_asked_of_offline_refusals() -> None:
    # session 42's 'maybe it was …' refusal: asked only where 'maybe' or 'perhaps' is said
    assert maybe_it_was42r in offline._REFUSALS
    assert maybe_it_was42r not in refusalguard.asked(offline._REFUSALS, "Give Bob the cup.")
    assert maybe_it_was42r in refusalguard.asked(
        offline._REFUSALS, "Give the cup to Alice, or maybe it was Bob."
    )
    asked = refusalguard.asked(offline._REFUSALS, "Give Bob the cup.")
    assert len(asked) < len(offline._REFUSALS)
    # the order is kept
    assert asked == [r for r in offline._REFUSALS if r in asked]


@pytest.mark.usefixtures("fresh")
def test_guards_kept_per_tuple(monkeypatch: pytest.MonkeyPatch) -> None:
    # a test that takes a refusal out gives offline another tuple: its guards are read for it
    fewer = tuple(r for r in offline._REFUSALS if r is not maybe_it_was42r)
    monkeypatch.setattr(offline, "_REFUSALS", fewer)
    asked = refusalguard.asked(offline._REFUSALS, "Maybe give Bob the cup.")
    assert maybe_it_was42r not in asked
    assert len(refusalguard.guards_of(fewer)) == len(fewer)


@pytest.mark.usefixtures("fresh")
def test_most_refusals_guarded() -> None:
    fns = refusalguard.all_refusals()
    rules = [r for r in refusalguard.guards_of(fns) if r is not None]
    assert len(rules) >= 30, len(rules)


@pytest.mark.usefixtures("fresh")
@pytest.mark.parametrize("part", ["tuning", "blind45", "blind48", "causes17"])
def test_none_unasked_would_refuse(part: str) -> None:
    """Every refusal and check the index leaves out for an entry's text (as said and lower-cased)
    raises nothing when asked all the same."""
    root = Path(__file__).resolve().parents[2]
    corpus = load_corpus(root / CORPUS_DIR / f"{part}.yaml", root)
    left_out = 0
    for entry in corpus.entries:
        scene = corpus.scenes[entry.scene]
        lexicon = Lexicon.of(scene)
        try:
            node = offline.parse_instruction(entry.text, scene)
        except GroundingError:
            node = None
        for text in (entry.text, entry.text.lower()):
            asked = refusalguard.asked(offline._REFUSALS, text)
            for refuse in offline._REFUSALS:
                if refuse not in asked:
                    left_out += 1
                    refuse(text, lexicon)  # raises nothing
            if node is None:
                continue
            asked = refusalguard.asked(offline._CHECKS, text)
            for check in offline._CHECKS:
                if check not in asked:
                    left_out += 1
                    check(text, node, lexicon)
    assert left_out > len(corpus.entries)


def test_committed_list_is_used() -> None:
    # the committed list's guards that still hold are used (a stale entry: the function asked)
    fns = refusalguard.all_refusals()
    rules = refusalguard.guards(fns, _refusal_guards.GUARDS)
    for fn, rule in zip(fns, rules, strict=True):
        entry = _refusal_guards.GUARDS.get(refusalguard.stepguard.key(fn))
        if rule is not None:
            assert isinstance(entry, tuple) and rule == entry[1]
