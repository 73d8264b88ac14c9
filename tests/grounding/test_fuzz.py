"""The fuzz's generator (tests/grounding/fuzz.py) makes what it says: the take-back family of
session 25 (taken back: refused; taken back and replaced: the new handover; an earlier object let
go before the entry: the entry), and the wrappers of a seed unchanged by it."""

from __future__ import annotations

import random
import re

import pytest

from hltl.bench.grounding import Entry, parse_expectation
from hltl.grounding.lexicon import Lexicon, lex
from hltl.grounding.tree import Task, tasks
from hltl.world.scene import Scene
from tests.grounding import fuzz
from tests.grounding.helpers import CELL, CLASSROOM, OFFICE

PARTS = ("tuning", "blind21", "blind23")


def _people_named(text: str, scene: Scene) -> set[str]:
    refs = {r for it in lex(text, Lexicon.of(scene)) if it.kind == "ent" for r in it.refs}
    return {r.id for r in refs if r.kind == "human"}


def _entry(scene: str, text: str, want: str | None) -> Entry:
    return Entry(scene, text, parse_expectation(want) if want is not None else None)


def _takebacks(entry: Entry, scene: Scene, seed: int) -> list[fuzz.Variant]:
    return list(fuzz.takebacks("t", entry, scene, random.Random(seed)))


def _pattern(form: str) -> str:
    """A form as a pattern: '{o}' and '{p}' become the groups o and p."""
    out = re.escape(form)
    for key in ("o", "p"):
        out = out.replace(re.escape("{" + key + "}"), f"(?P<{key}>.+?)")
    return out


def _found(forms: tuple[str, ...], text: str, at: str) -> re.Match[str] | None:
    """The form of ``forms`` ``text`` ends with (``at="end"``; a "." form may follow a "?") or
    starts with (``at="start"``), or None."""
    for form in forms:
        if at == "start":
            m = re.match(_pattern(form), text)
        else:
            m = re.search(_pattern(form) + "$", text)
            if m is None and form.startswith("."):
                m = re.search(_pattern(form[1:]) + "$", text)
        if m:
            return m
    return None


def _match(forms: tuple[str, ...], text: str, at: str) -> re.Match[str]:
    m = _found(forms, text, at)
    assert m is not None, f"{text!r} has none of {forms}"
    return m


def _one_object(name: str, scene: Scene) -> str:
    (oid,) = fuzz._objects_named(name, scene)
    return oid


def _one_person(name: str, scene: Scene) -> str:
    (hid,) = _people_named(name, scene)
    return hid


@pytest.mark.parametrize("seed", range(40))
def test_a_one_handover_entry_gets_all_three_kinds(seed: int) -> None:
    said = "Give Bob the apple, please."
    taken, replaced, let_go = _takebacks(_entry("cell", said, "apple>B"), CELL, seed)
    # taken back: the entry's words, then a form that takes it back; refused
    assert taken.want is None and taken.must == "refuse" and taken.family == "takebacks"
    assert taken.text.startswith("Give Bob the apple, please")
    m = _match(fuzz.TAKEN_BACK, taken.text, "end")
    if m.groupdict().get("p"):
        _one_person(m["p"], CELL)
    # replaced: a handover of another one-of-a-kind object to a person, both named in the form
    assert isinstance(replaced.want, Task) and replaced.must == "same"
    assert replaced.want.kind == "deliver" and replaced.want.obj != "apple"
    assert replaced.want.obj in fuzz._unique_objects(CELL)
    assert replaced.text.startswith("Give Bob the apple, please")
    m = _match(fuzz.REPLACED, replaced.text, "end")
    assert _one_object(m["o"], CELL) == replaced.want.obj
    assert _one_person(m["p"], CELL) == replaced.want.target
    # let go: an object the entry does not name, before the entry, which must read as before
    assert let_go.want == parse_expectation("apple>B") and let_go.must == "same"
    m = _match(fuzz.LET_GO, let_go.text, "start")
    assert _one_object(m["o"], CELL) not in {"apple"}
    assert let_go.text[m.end() :] in (said, "g" + said[1:])  # lower case after a comma


@pytest.mark.parametrize("seed", range(20))
def test_after_a_question_only_sentences_follow(seed: int) -> None:
    entry = _entry("cell", "Could you give Carol the bottle?", "bottle>C")
    made = _takebacks(entry, CELL, seed)
    assert len(made) == 3
    for v in made[:2]:
        assert v.text.startswith("Could you give Carol the bottle? ")
        assert v.text[len("Could you give Carol the bottle? ")].isupper()


def test_a_refused_entry_is_only_taken_back() -> None:
    (only,) = _takebacks(_entry("cell", "Give her the cup.", None), CELL, 3)
    assert only.must == "refuse" and only.text.startswith("Give her the cup")


@pytest.mark.parametrize("seed", range(20))
def test_an_entry_of_two_objects_or_a_choice_is_not_replaced_or_let_go(seed: int) -> None:
    two = _entry("cell", "Give Bob the apple and the bottle.", "apple>B & bottle>B")
    taken, let_go = _takebacks(two, CELL, seed)  # not replaced: the form could replace either
    assert taken.must == "refuse" and let_go.want == two.want
    assert _one_object(_match(fuzz.LET_GO, let_go.text, "start")["o"], CELL) not in {
        "apple",
        "bottle",
    }
    # a choice is neither replaced nor let go ("forget the cup" could narrow "a mug or the cup")
    choice = _entry("cell", "Give Bob the apple or the bottle.", "apple>B | bottle>B")
    assert [v.must for v in _takebacks(choice, CELL, seed)] == ["refuse"]


def test_a_name_keeps_its_capital_after_an_opener() -> None:
    named = _entry("office", "Priya needs the stapler.", "stapler>A")
    assert all("Priya needs" in _takebacks(named, OFFICE, s)[-1].text for s in range(30))
    verb = _entry("classroom", "Hand the globe to Noah.", "globe>B")
    seen = {_takebacks(verb, CLASSROOM, s)[-1].text for s in range(30)}
    assert any(t.endswith(", hand the globe to Noah.") for t in seen)
    assert any(t.endswith(". Hand the globe to Noah.") for t in seen)


def test_over_the_corpus_each_variant_names_what_it_says() -> None:
    kinds: dict[str, int] = {"taken": 0, "replaced": 0, "let go": 0}
    for v, scene in fuzz.generated(PARTS, seed=25, every=7, families=("takebacks",)):
        assert v.family == "takebacks"
        if v.want is None:
            kinds["taken"] += 1
            assert v.must == "refuse"
            m = _match(fuzz.TAKEN_BACK, v.text, "end")
            if m.groupdict().get("p"):
                _one_person(m["p"], scene)
        elif isinstance(v.want, Task) and (r := _found(fuzz.REPLACED, v.text, "end")):
            kinds["replaced"] += 1
            assert v.must == "same"
            assert _one_object(r["o"], scene) == v.want.obj
            assert _one_person(r["p"], scene) == v.want.target
        else:
            kinds["let go"] += 1
            assert v.must == "same"
            m = _match(fuzz.LET_GO, v.text, "start")
            assert _one_object(m["o"], scene) not in {t.obj for t in tasks(v.want)}
    assert min(kinds.values()) > 20, kinds


def test_the_wrappers_of_a_seed_do_not_change_with_the_takebacks() -> None:
    alone = [v for v, _ in fuzz.generated(PARTS, seed=25, every=11, families=("wrappers",))]
    both = [v for v, _ in fuzz.generated(PARTS, seed=25, every=11)]
    assert [v for v in both if v.family == "wrappers"] == alone
    assert len(both) > len(alone) and {v.family for v in both} == set(fuzz.FAMILIES)


def test_an_unknown_family_is_an_error(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        fuzz.main(["--families", "wrappers,nope", "--parts", ""])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert "error: --families: no family called 'nope'" in err
    assert "expected some of ('wrappers', 'takebacks')" in err
