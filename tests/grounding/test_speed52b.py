"""Session 52 (12b): `_forgot_choice50l` asks for remarks only beside a choice, as it refused."""

from __future__ import annotations

import pytest

from hltl.bench.grounding import CORPUS_DIR, load_corpus
from hltl.errors import GroundingError
from hltl.grounding import _rewrites50l
from hltl.grounding._rewrites49l import choice_forgotten49l, forgot49l
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Group, Node, Task
from tests.grounding.helpers import ROOT

# parts whose sentences hold the speaker's forgetting remarks (blind47-blind50's refusals with
# readings) and many without
_PARTS = ("blind47", "blind48", "blind49", "blind50")


def _before(text: str, node: Node, lexicon: Lexicon) -> None:
    """The check as it was before session 52 (kept here to compare)."""
    if _rewrites50l.forgets50l(text) is not None or forgot49l(text):
        choice_forgotten49l(node, lexicon)
    said = _rewrites50l.unknowing50l(text, lexicon)
    if said is not None:
        choice_forgotten49l(
            node, lexicon, f"{said!r} could say the speaker does not know which was asked for"
        )


def _verdict(check: object, text: str, node: Node, lexicon: Lexicon) -> str | None:
    assert callable(check)
    try:
        check(text, node, lexicon)
    except GroundingError as e:
        return str(e)
    return None


def _readings(lexicon: Lexicon) -> list[Node]:
    """Readings of the scene's things and people: without a choice, and with one (alone, inside
    an 'and', inside a sequence)."""
    scene = lexicon.scene
    objs = [o.id for o in scene.objects]
    people = [h.id for h in scene.humans]
    first = Task("deliver", objs[0], people[0])
    second = Task("deliver", objs[-1], people[-1])
    choice = Group("or", (first, Task("deliver", objs[0], people[-1])))
    return [
        first,
        Group("and", (first, second)),
        Group("seq", (first, Group("and", (second, first)))),
        choice,
        Group("and", (second, choice)),
        Group("seq", (first, Group("and", (second, choice)))),
    ]


@pytest.mark.parametrize("part", _PARTS)
def test_the_check_refuses_what_it_refused_before(part: str) -> None:
    corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
    refused = 0
    for entry in corpus.entries:
        lexicon = Lexicon.of(corpus.scenes[entry.scene])
        for node in _readings(lexicon):
            new = _verdict(_rewrites50l._forgot_choice50l, entry.text, node, lexicon)
            assert new == _verdict(_before, entry.text, node, lexicon), entry.text
            refused += new is not None
            if not _rewrites50l._has_choice50l(node):
                assert new is None
    assert refused > 0  # the remarks are there, and refused beside a choice


def test_has_choice_finds_an_or_at_any_depth() -> None:
    a, b = Task("deliver", "cup", "A"), Task("place", "cup", "shelf")
    assert not _rewrites50l._has_choice50l(a)
    assert not _rewrites50l._has_choice50l(Group("seq", (a, Group("and", (a, b)))))
    assert _rewrites50l._has_choice50l(Group("or", (a, b)))
    assert _rewrites50l._has_choice50l(Group("seq", (a, Group("and", (b, Group("or", (a, b)))))))
