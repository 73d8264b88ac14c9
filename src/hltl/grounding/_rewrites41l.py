"""The grounder's rules of session 41, the lead (docs/grounding.md)."""

from __future__ import annotations

from collections.abc import Callable

from hltl.errors import GroundingError
from hltl.grounding import gate as re
from hltl.grounding._normalise1 import _F, _ids
from hltl.grounding._normalise4 import _fit36
from hltl.grounding.lexicon import Lexicon
from hltl.grounding.tree import Node, tasks

# -- session 41 (lead): a handing or placing told as done ----------------------------------------
#
# "The chips were handed to Bob, so give Alice the cup." read `chips>B & cup>A`, "The cup has been
# given to Alice." `cup>A` and "The cup's been put on the shelf." `cup@shelf`: the grammar's
# passive ("the cup is handed to Bob", "… should be given to …") took any auxiliary, the past
# ones too. A past or perfect passive of a verb of handing or placing, said of a scene object
# with a person or a surface after it, tells what has been done, not what to do: refused. Kept:
# the present and the modal passives (a goal said as a state: "the cup is put on the shelf", "the
# cup will be given to Alice"), a subordinate clause ("after Bob has been given the chips", "if
# the apple were placed on the counter", "the cup that was given to Alice"), a person as the
# subject ("she's been stuck on the phones", "Bob's been stood there for ages").
_HANDLED41L = (
    r"given|handed|passed|brought|taken|delivered|put|placed|moved|sent|set|left|dropped|stood|"
    r"hung|popped|stuck|carried|fetched|returned|laid|stacked|stored|shifted|lent|loaned"
)
_DONE_TAIL41L = (
    r"\s*(?P<said>\b(?:was|were)|(?:\b(?:has|have|had)|(?<=\w)['’]s)\s+"
    r"(?:already\s+|just\s+)?been)\s+(?:already\s+|just\s+)?(?:" + _HANDLED41L + r")\b"
    r"(?P<rest>\s+(?:(?:over|across|back|up|down|out|away)\s+)?(?:to|on|onto|in|into)\b"
    r"[^,.;:!?]*)"
)
_DONE41L = re.compiled(r"(?P<subject>[^,.;:!?]*?)" + _DONE_TAIL41L, _F)
# Session 52 (12p): the pattern without its subject. Every match of _DONE41L ends in a match of
# it, so where it finds nothing, _DONE41L finds nothing either: asked first, as the lazy subject
# tried from every letter of a clause cost ~0.25 ms a text holding 'was', 'were' or 'been'
_DONE_SAID41L = re.compiled(_DONE_TAIL41L, _F)
_SUBORDINATE41L = re.compiled(
    r"\b(?:if|after|once|when|whenever|until|till|before|unless|soon as|so that|that|which|who|"
    r"whether|where|since|because)\b",
    _F,
)


def _done41l(text: str, lexicon: Lexicon) -> None:
    """Session 41 (lead): 'the chips were handed to Bob', 'the cup has been given to Alice', 'the
    cup's been put on the shelf' — a handing or placing told as done — refused, not read as a
    request."""
    low = text.lower()
    if "been" not in low and "was" not in low and "were" not in low:
        return
    if _DONE_SAID41L.search(text) is None:
        return
    for m in _DONE41L.finditer(text):
        subject = m.group("subject")
        if _SUBORDINATE41L.search(subject):
            continue
        if not _ids(subject, lexicon, "object") or _ids(subject, lexicon, "human"):
            continue
        rest = m.group("rest")
        if not (_ids(rest, lexicon, "human") or _ids(rest, lexicon, "surface")):
            continue
        said_as_done41l(m)


def said_as_done41l(m: re.Match[str]) -> None:
    """Refuse the report ``m`` (its group 'said' the verb that tells it as done)."""
    said = m.group(0).strip()
    raise GroundingError(
        f"{said!r} is said as done ({m.group('said').strip()!r}), not as something to do: "
        "say the request without it, e.g. 'give Bob the chips' or 'put the cup on the shelf'"
    )


# -- session 41 (lead): a want taken back by an idiom, of what the reading hands that person --
#
# 12c's `idioms` fuzz: "Give Bob the cup. Bob has gone off the cup." read `cup>B` (the sentence
# was dropped as a remark about the request's person and thing), as did "…, Bob is through with
# the cup", "…. He's so over it.", "… has lost interest in the bottle", and "Bob is so over the
# cup." read `cup>B` (as 'is after'). A person said to have got a thing already ('has already
# got', 'has got it already'), or to have gone off, be over, be sick / tired / fed up / bored of,
# be through / finished / done with, have had enough of, have lost interest in or have gone cold
# on it (or 'it', 'them'), has it or no longer wants it: a reading that hands them that thing is
# refused (a negation word was refused already). A placement beside it ("hang the
# tongs on the rack, Marco's done with them") and a thing the person does not get read as before;
# 'he / she is done / finished with it' is left to session 36's `offline._use_said36s`, which
# weighs it against the reading (and its tests take that rule out).
_TAKEN_BACK41L = re.compiled(
    r"\b(?P<who>he|she|they|(?:person|mr|mrs|ms|miss|dr) [a-z]+|[a-z]+)"
    r"(?:['’]s|\s+(?:is|was|has|had|have|are|were))?\s+(?:(?:so|totally|completely|well|really|just|now|already|all|rather)\s+)*"
    r"(?P<idiom>(?<=already )got|got(?= (?:it|them|that|those|the [a-z]+(?: [a-z]+)?) already\b)|"
    r"gone (?:right |completely )?off|gone (?:cold|sour) on|over(?! the moon\b)|"
    r"(?:sick|tired|bored) (?:of|with)|fed up (?:of|with)|through with|finished with|done with|"
    r"had (?:quite )?enough of|had it up to here with|lost (?:interest|his appetite|her "
    r"appetite) (?:in|for)|cooled (?:on|off on)|off the idea of)\s+(?P<x>(?:the |that |those |"
    r"his |her |their )?[a-z]+(?: [a-z]+){0,3}|it|them|that|those)",
    _F,
)


def _taken_back41l(text: str, node: Node, lexicon: Lexicon) -> None:
    """Session 41 (lead): a person said to no longer want a thing the reading hands them
    (above): refused."""
    for m in _TAKEN_BACK41L.finditer(text):
        who, x = m.group("who"), m.group("x")
        people = _ids(who, lexicon, "human")
        if not people and who.lower() in ("he", "she", "they"):
            if m.group("idiom").lower().startswith(("done", "finished")):
                continue  # session 36's offline._use_said36s weighs these against the reading
            humans = {h.id for h in lexicon.scene.humans}
            people = {
                t.target
                for t in tasks(node)
                if t.target in humans and (who.lower() == "they" or _fit36(t.target, who, lexicon))
            }
        things = _ids(x, lexicon, "object")
        pointed = x.lower() in ("it", "them", "that", "those")
        for t in tasks(node):
            if t.target in people and (t.obj in things or (pointed and not things)):
                said = m.group(0).strip()
                raise GroundingError(
                    f"{said!r} says the person has it already or no longer wants it, yet the "
                    f"reading has {t.obj}>{t.target}: say what to do; to drop a task, say "
                    "'cancel …'"
                )


# -- session 41 (lead): an ordinal beyond what the scene has ---------------------------------------
#
# blind40's one wrong reading at its measurement: "Hand the bottle to Person A. Hand her the second
# bottle as well." (a scene with one bottle) read `bottle>A`: 'second' was dropped and the second
# handing of the same bottle merged into the first. 'the / a second (third, fourth, fifth) X' where
# the scene has fewer things that X names than the ordinal counts is refused naming how many there
# are; with enough of them the older rules ask which one ('mug' is ambiguous).
_ORDINAL41L = re.compiled(
    r"\b(?P<nth>second|third|fourth|fifth)\s+(?!(?:the|a|an|his|her|their|one|of|to|for|and|then)\b)"
    r"(?P<x>[a-z]+(?:\s+[a-z]+)?)",
    _F,
)
_NTH41L = {"second": 2, "third": 3, "fourth": 4, "fifth": 5}


def _ordinal41l(text: str, lexicon: Lexicon) -> None:
    """Session 41 (lead): 'the second bottle' in a scene with one bottle (above): refused."""
    if not any(w in text.lower() for w in _NTH41L):
        return
    for m in _ORDINAL41L.finditer(text):
        said = m.group("x").split()[0]
        things = _ids(said, lexicon, "object")
        if not things:
            said = m.group("x")
            things = _ids(said, lexicon, "object")
        if not things:
            continue
        n = _NTH41L[m.group("nth").lower()]
        if len(things) < n:
            have = ", ".join(sorted(things))
            raise GroundingError(
                f"{m.group('nth')} {said!r}: the scene has {len(things)} ({have}), not "
                f"{n}: say which thing you mean"
            )


# refusals asked of the text before it is read (offline._parse, after the engineers' ones)
REFUSE41L: tuple[Callable[[str, Lexicon], None], ...] = (_done41l, _ordinal41l)
# checks of the whole instruction's reading (offline.parse_instruction, after the engineers' ones)
CHECK41L: tuple[Callable[[str, Node, Lexicon], None], ...] = (_taken_back41l,)
