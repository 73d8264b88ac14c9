"""The wrapper fuzz of the paraphrase corpus (issue 12; docs/grounding.md, "Fuzz").

Every entry of every part is said again inside words that change nothing (openers, closers, both
together), which must read as the entry does (or be refused); with remarks that name, hedge or ask
for the speaker, or closers that delay or add, which must be refused; and, for an entry of one
handover, corrected to another object (which must read as that object to that person, or be
refused) or with a correction cut off or left open (refused). A second family (session 25),
take-backs: the request taken back after it ("…, no, leave it", "… Actually, never mind."; refused),
taken back and replaced by another handover ("… Actually, never mind that. The <object> to
<person> instead."; that handover, or refused), and an object of an earlier request let go before
it ("Never mind the <object>, …"; as the entry, or refused). A third family (session 26),
references: an entry's one object of a kind the scene has several of named by its kind alone ("the
blue blanket" said as "the blanket", "the one blanket", "that blanket"), or its one person of a
title two share by the title ("Mrs Khan" as "the patient"), refused with the readings; the same in
short requests, wants and corrections of the scene; "the one <object>" of a one-of-a-kind object
(that handover); and the speaker's own want joined to an entry ("We need the <object>, …"; refused).
A fourth family (session 27), exclusions: a request that narrows a kind the scene has several of
after a comma ("Give <person> a <kind>, just not the <colour> one.": the rest, a choice; "… the
<kinds>, just not the <colour> one": the rest, all; "Both <kinds> to <person>, sorry, just the
<colour> one": that one; "The <kinds> to <person>, sorry, just the one": refused with the
readings), bare or inside a wrapper's opener and closer (mostly both, the kind session 27 found
misread); and every entry narrowing after a comma ("…, just not …", "…, sorry, just the one")
inside an opener and a closer (as the entry, or refused). A fifth family (session 28), tails: a
sentence after an entry that adds a handover ("… Also, give <person> the <object>."; the entry's
reading, neither loosened nor dropped, and that handover) or that must be refused ("… Then I want
the <object>.", "… Hmm, or maybe not."). A sixth family (session 29), asides: a remark naming
nothing of the scene before an entry ("Sorry, typing this from the car park. …", "For tomorrow's
picnic, …") and after it ("…, while the kettle boils."), and a trade after a person's name
("Alice the baker", "… to Mr Novak, the plumber."): as the entry, or refused. A seventh family
(session 30), afterthoughts: for an entry of one handover naming its one person, that person
corrected after it ("…, oh hang on, <person> rather", "… Scratch that, <person>.", with or without
a reason naming nothing: "…, sorry, I meant <person>, I mixed them up"; that handover to that
person, or refused) or left undecided ("…, or <person> maybe, I can't remember which"; refused); a
person's state said before or after a grounded entry with no choice ("<Person> is parched. …"; the
entry, or refused: a state asks for nothing); and the count of an entry's handovers restated after
it ("… That's two things in all."; the entry, or refused) or miscounted (refused). An eighth family
(session 31), frames: an entry's one handover said as a want in a frame ("What <person> needs is
the <object>.", "It's the <object> <person> is after.") or as a want the speaker was told of
("<Person> wants the <object>, I'm told."): that handover, or refused; that want negated, had
already or past ("What <person> doesn't need is …", "I'm told <person> has the <object> already.",
"The last thing <person> wants is …"): refused; a want frame after a grounded entry adding a
handover of an object it does not name (the entry's reading and that handover); and a person
described between commas after their name in an entry ("Alice, our oboist, would like …"): as the
entry, or refused. A ninth family (session 32), repairs: an object or a person of an entry said
after another one and a filler or a word of repair ("the cup, er, the chips", "Carol, sorry,
Bob"), or a name begun and said again ("Person, er, Person A"): as the entry, or refused; an
object left undecided between two ("the cup or, er, the chips, I forget which"): refused; and,
for an entry of one task, another object added before its own with "and" ("the cup and, er, the
chips"): that task of both objects, or refused. A tenth family (session 33), deferrals: words
after an entry or before it that hand part of the decision to someone else or leave it open
("… Then whatever the deckhand tells you.", "…, and see what Sam says.", "Check with Sam first.
…"): refused, the plan would be incomplete; and a sentence that only closes the request ("… Then
you're done.", "… That's all for now."): as the entry, or refused; and (session 34) a choice left
up to the robot ("…, it's up to you.", "… Also, give Sam the cup or the pen, it's up to you
which."): the entry's choice, or that choice added. An eleventh family (session 34), clefts: an
entry's one handover said as a pseudo-cleft or an it-cleft ("It's Bob who gets the chips.", "The
chips are what Bob's after.", "Bob is the one to have the chips."), with another person set
against the one named ("It's Bob, not Alice, who gets the chips."): that handover, or refused;
negated ("It's not Bob who gets the chips.": no recipient) or said of a person the scene does not
have: refused; with a second object: both handovers; a cleft after an entry adding a handover: the
entry and that handover; and a placement's surface in a cleft ("The shelf is where the apple
goes."): that placement, or refused. A twelfth family (session 35), counts: a kind the scene
has several objects of said with a count or "both" for a person ("Give Bob the two mugs."): every
one of the kind to that person where the count agrees with the scene, refused where it does not
("the three mugs" of two, "both pens" of three); an entry's one-of-a-kind object said as the only
one ("the one apple": the entry) or as several ("both apples": refused); and an entry's kind in the
plural ("the mugs") said with its count (the entry) or another one (refused). A thirteenth family
(session 36), remarks: a remark after an entry that names nothing of the scene and asks nothing
(", the heating's off", ". It's for the bake sale."): as the entry, or refused; a delay after it
(", after lunch", ", once the meeting's over"): refused; and, for an entry of one handover naming
its one person, that person said not to want it (", Bob doesn't want it"): refused. Session 37 added
blind35's kinds to four families: corrections of the person ("…, hang about, I mean Carol"), wants
said by a verb of need ("Bob is desperate for the apple.") and given up ("Bob has gone off the
apple.": refused), "the pair of mugs" (as "both"), the speaker saying who they are (", I'm the
relief cook today") and a remark about a person of the scene by a name (", Alice is new here"; the
entry). Session 38 added blind36's kinds to five families: a remark about the entry's one person by
a pronoun (", she's just back from her pottery class"; the entry) and about a person by a name
before the entry ("Bob's had a long shift, so …"; the entry), a thing given up for the entry's own
("Bob doesn't need the cup any more, just the apple."; the entry's handover), more wants said by a
verb ("could do with", "would love", "'s after") and given up ("doesn't need … any more"), one of a
kind for a person ("Give Bob any of the mugs, whichever's nearer."; a choice of each), another
person set against the one named ("Alice shouldn't get the apple; Bob should.") and the person
corrected with who wants it (", actually, it's Carol who asked for it"). Session 39 added blind37's
closing remarks, said by subjects and in places blind37 did not use (`remarks39`, its own
generator): a pronoun before the request ("She's had a morning of it at the allotments, so …"),
"his/her X" or a name's possessive after it (", his knee's playing up again"), "we" and the place
before or after it (", we've got the inspectors in", "The back door's jammed. …"), a sentence
between two of the request's, and a "who" clause after a name ("Give Bob, who's new here, the
apple."): the entry, or refused. A fourteenth family (session 40), purposes: blind38's purpose "for
<an event, a pastime, a group>" beside a request, with words no earlier part uses: after it with or
without a comma ("… for the harvest supper."), before it ("For the ramblers, …"), after its one
object inside it ("Give the apple for the cricket tea to Bob."), as a sentence after it (". That's
for the stamp fair."), and "his/her/their <pastime>" after an entry of one handover naming its one
person, fitting that person or another ("Give Bob the apple for her wild swim."): the entry, or
refused; a purpose as an object's only recipient ("The apple for the ramblers.") and the request
said after it to be for a later time (", it's for tonight"): refused. A fifteenth family (session
41), idioms: blind39's want, choice and exclusion idioms said by idioms blind39 does not use, over
grounded entries: an entry's one handover said by a want idiom ("Bob is dying for the apple.",
"Bob has a hankering for the apple."): that handover; after an entry for another object: the entry
and that handover; the want taken back ("Bob can do without the apple.", "Bob has gone off the
apple.", "Bob is so over the apple."), alone or after the entry: refused; a choice left to the
robot between two objects, the objects of a kind or two people ("Give Bob the apple or the cup,
take your pick.", "Bob gets a mug, suit yourself which."): that choice; of a kind the scene lacks:
refused; and an exclusion idiom ("Give Bob the mugs, all but the red one.", "Give Bob everything
but the apple."): every other one of the kind, or of the scene. A sixteenth family (session 42),
turns: blind40's negations and exclusions, corrections and courtesy question forms said by idioms
blind40 does not use, over grounded entries: an entry's one handover said with another object not
for that person ("Not the cup, Bob gets the apple.", "Bob has no need of the cup; give Bob the
apple."), two others neither ("Neither the cup nor the chips; the apple for Bob."), another person
not the one ("Carol's not getting the apple, Bob is.") or proposed and agreed to ("Why not give
Bob the apple? Yes, go on."): that handover; the object or the person corrected after the entry
(". My mistake, I meant the cup.", ". Make that Carol."): that correction; the entry asked as a
courtesy ("Would you be so good as to give Bob the apple?"): the entry; "everything except the
apple" and "the mug that isn't the red one": every other object, the other one; and refused: a
correction that could replace or add (with both objects as readings), a correction to a thing the
scene lacks, a proposal dropped, a question that only asks whether, "the box that isn't the small
one" of three (with the rest as readings) and every one of a kind left out; and a variant that
reads said in lower case and with a typo. A seventeenth family (session 43), said: a request framed
the way people say it, by words blind41 does not use, over grounded entries: a reason or state of an
entry's one person said before it ("Bob has been bell-ringing all evening, so …"): the entry; its
one handover said by a comparison or hyperbole ("Bob would walk over hot coals for the apple.") or
hung on a condition about others' claims, the speaker's hedge ("If nobody's bagsied the apple, Bob
can have it."; the lead's decision, session 43): that handover; a kind dealt out ("Alice and Bob get
a mug apiece.", "The mugs: one for Alice and one for Bob."): each a different one, every way as a
choice; two objects 'respectively' ("Give Alice and Bob the cup and the apple respectively."): in
that order; an object back to its owner or someone's object to another ("Take Bob's apple back to
him.", "Take Carol's apple over to Bob."): that handover; and refused: the handover hung on an
outside event or a later word ("If it stops raining, give Bob the apple."), the hyperbole said
against ("Bob wouldn't be seen dead with the apple."), a distribution the scene cannot satisfy
(three people a mug apiece of two, three objects to two people 'respectively') and an owner who
could be either of two ("Give the apple back to whichever of Alice and Bob had it."; both as
readings); lower case and a typo as in turns. An eighteenth family (session 44), holds: a remark
that a person of the scene already holds, still has or has had a one-of-a-kind object an entry
neither names nor moves, or has their own one, before or after a grounded entry saying no pronoun
for a person ("Alice's got the cup already, so …", "…. Alice is holding the cup already.", "…;
Alice's got her own cup."), and one of them in lower case: the entry, or refused — what a person
holds asks for nothing, so a handover of that object read from the remark is wrong (session 44's
probes: "Mrs Khan's got her jug; give Mr Lee the magazine." read jug>C & magazine>B). A nineteenth
family (session 45), texted: a grounded entry typed the way people text (blind43's run-ons: "lilys
thirsty after her nap so sippy cup to her"), without its stops and commas ("Give Bob the apple
won't you"), without its apostrophes ("Bobs after the apple"), both in lower case, and, for an
entry of one handover naming its one person, with a reason of that person run on after it ("give
bob the apple hes been after it all morning"): the entry, or refused. A twentieth family (session
46), antecedents: an entry's one handover of a one-of-a-kind object to a person whose name says
their sex, that person said by the name in a remark, a state or a want and the handover then asked
for with a pronoun for them (blind44's "That apple was set aside for Person A at the swan upping;
run it over to her."; "Carol's parched after the fell race, she needs the apple.", "The apple is
Bob's. Hand it across to him, thanks."), and in lower case: that handover, or refused; two people
of that sex said before the pronoun ("Alice and Carol are both parched; she needs the apple."):
refused, both as readings; someone not in the scene said before it ("My sister's parched after
the fell race, she needs the apple."): refused. A twenty-first family (session 47), thoughts: an
entry's one handover of a one-of-a-kind object said as what the speaker thought and taken back
after 'but' (blind45's one wrong reading, "Marco's shouting for salt, I thought, but it was lemon he
wanted, …", and its corrections "well, I heard white, but he corrected me: it's the green cup he's
after"): for another object ("Bob wants the apple, I thought, but it was the cup Bob wanted."; that
object to that person) or another person ("…, but it was Carol who asked for it."; to them); added
to ("…, I think, but it's the cup Bob wants too."; both) or put after another ("…, but it's the
cup Bob needs first."; the other, then the entry's); and a hedge after the entry, alone (", I
think.") or with where its object is (", I think, but it's on the shelf."): the entry — where a
thing is asks for nothing (session 47's probes: "Marco wants the salt, I think, but it's on the
rack." read salt@rack). Each may be refused instead. A twenty-second family (session 48), chains:
a second correction after a first (tuning's "Hand the apple to Bob, no, to Carol, well, the crisps
actually." read apple>C & chips>C; "Crisps over to Bob, or, hmm, Alice, so Alice." a choice of
three). After an entry's one handover of a one-of-a-kind object to a person named: the person then
the object ("…, no, Carol, well, the crisps actually."), the object then the person, the object
or the person twice ("…, I mean Alice, or rather Carol."): the last of each; corrected and put
back ("…, no, the cup, no, sorry, I had it right the first time: the apple."): the entry; a
hesitation between people ("…, or, hmm, Alice, or Carol, so Carol."): the one it settles on; the
person corrected, then a placing instead: that placing; a second object added and then one of the
two corrected ("…, and the cup, no, Carol, well, the crisps actually."): refused, both as
readings. After an entry's one placing of a one-of-a-kind object naming no person: the surface
corrected, then a handover instead, put back, or the object corrected. Each may be refused
instead. A twenty-third family (session 49), forgets: a choice closed by a remark that the speaker
has forgotten or never knew which, without 'which' (blind47's wrong reading "Kofi wanted one of the
spanners for the stonecarver's job, the small or the large, it's gone clean out of my head." was
read as the robot's choice): after an entry with a choice in it not said to be free ("…, I wasn't
listening."), and an entry's one handover of a one-of-a-kind object said as the person's want of
it or another ("Bob wanted the apple or the cup, I've clean forgotten.") or as it for the person or
another ("Alice or Bob wanted the apple, memory's shot."): refused (the choice is the person's, and
the speaker lost it), the two objects as readings. A twenty-fourth family (session 49), lots: 'the
whole lot' in apposition (blind47's "Load the belt with the three boxes, the whole lot, …" read
every object of the depot): after a kind's plural naming every one of the kind, for the entry's
person ("Give Bob the mugs, the whole lot.", "Give Bob the lot, the mugs.", "… the mugs - the
whole lot.") or on a surface: every one of the kind; after the entry's one-of-a-kind object and
another ("Give Bob the apple and the cup, the whole lot."): those again or everything else,
refused, both as readings. Session 50 widens forgets to the five meanings of the lead's
`forgets50l` and the wordings it missed ("…, I'm drawing a blank.", "…, I'd have to check.") and
adds a form `free`: a remark after a choice that is no forgetting ("…, I don't mind which."): the
choice stands. A twenty-fifth family (session 50), kin: a he / she who wants, or a him / her who is
given, said of a person the scene names by a word of kin or a title of the other sex ("Grandad
says she's been asking for the teddy.", "Mr Lee's asked for the jug, let her have it."): refused;
of that person's own sex, where no one else of the scene is of it ("Grandad says he wants the
teddy."): the object to that person. A twenty-sixth family (session 51), done: an entry's one
handover of a one-of-a-kind object to a person named, said as already done or as never a request
(12c's session-51 probes, read as requests: "Gave Bob the apple.", "The apple went to Bob.",
"You brought Bob the apple.", "Great job getting the apple to Bob.", "Bob, our new starter, had the
apple.", "Alice says Bob has the apple.", "Bob or Alice had the apple."), or said and then seen to
("…, it's sorted.", "…, I'll see to it myself."): refused; and a checklist that ticks it off before
another handover ("The apple to Bob: done. The cup to Bob, please.") or a want replaced ("Bob
wanted the apple, now Bob wants the cup."): the other handover only.

Run it whole by hand (it takes minutes; under /work/notes/bench.sh at nice on a shared machine):
``env PYTHONPATH=src:. .venv/bin/python -m tests.grounding.fuzz --seed 16``; a test runs a small
sample of it.
"""

from __future__ import annotations

import argparse
import random
import re
import sys
from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass
from itertools import permutations
from pathlib import Path
from typing import Literal, cast, get_args

from hltl.bench.grounding import CORPUS_DIR, PARTS, Entry, load_corpus, show_tree
from hltl.errors import GroundingError
from hltl.grounding.lexicon import Lexicon, lex
from hltl.grounding.offline import parse_instruction, spec_of
from hltl.grounding.tree import Group, Node, Task, has_choice, tasks
from hltl.spec.equivalence import counterexample
from hltl.world.scene import Scene

ROOT = Path(__file__).resolve().parents[2]

# words around a request that ask nothing (each must leave the reading as it is)
OPENERS = (
    "Right, ",
    "Okay, so, ",
    "Hiya! ",
    "Good morning. ",
    "Let me think... ",
    "Order's up so ",
    "Robot, ",
    "Hey robot, ",
    "Morning! ",
    "Sorry to bother you, but ",
    "I know you're busy, but ",
    "Okay darling, let's get you sorted. ",
    "Yes chef! ",
    "Good afternoon. When convenient, ",
    "Pretty please, ",
    "Cheers for that. One more favour, ",
    "I hope this is okay, ",
    "Oh, thank you so much for earlier. Now, ",
    "Right, eyes on me everyone. ",
)
CLOSERS = (
    ", before I go",
    ". That's all from me.",
    " and that's us done",
    ". Have a great day.",
    ". Good robot.",
    ". Regards.",
    ". Go.",
    ", go go go",
    ". Thanks!",
    ", cheers",
    ". Done.",
    ", if that's alright with you.",
)
# remarks that name, hedge or ask for the speaker, and closers that delay or add: refused
NEAR_OPENERS = (
    "I want the {o} too. ",
    "We need the {o}, ",
    "I'm not sure, ",
    "I'll need it back, so ",
    "Give me the {o} as well. ",
    "Not yet, ",
    "If {p} is here, ",
)
NEAR_CLOSERS = (
    ", before I go tomorrow",
    ". That's all from me and {p}.",
    ". I want one too.",
    ", and the {o} for me",
)
CORRECTIONS = (
    ", scratch that, the {o}",
    ", no, I tell a lie, the {o}",
    ", no wait, the {o}",
    ", correction, the {o}",
)
CUT_OFF = (", scratch that", ", or was it {p}...", ", no wait", ", correction,")

# take-backs (session 25; blind23's "no, leave it, Ava can get it herself", "Green book, leave it
# on the shelf"): the whole request taken back, refused ("." forms also after a question)
TAKEN_BACK = (
    ", no, leave it",
    ". Actually, never mind.",
    ". On second thoughts, forget it.",
    ", no, leave it, {p} can get it",
    ". Sorry, cancel that.",
    ". Oh, don't bother.",
    ", actually, forget the whole thing",
    ". No, wait, leave it, it's fine where it is.",
)
# taken back and replaced by another handover (after an entry of one task): that handover
REPLACED = (
    ". Actually, never mind that. The {o} to {p} instead.",
    ", no, leave it, give {p} the {o} instead",
    ". Forget that, sorry. Could you give {p} the {o}?",
    ". Cancel that. Just hand {p} the {o}.",
)
# an object of an earlier request let go before the entry (one the entry does not name): the entry
LET_GO = (
    "Never mind the {o}, ",
    "Forget the {o}. ",
    "Don't worry about the {o}. ",
    "Oh, never mind the {o}. ",
)
# references (session 26; blind24's "Ruth asked for the one blanket." read as either blanket, and
# the wrapper fuzz's "We need the chips, for Person B, bottle, please give.") : a kind named alone
# where the scene has several of it ({c}), with the readings; {u} a one-of-a-kind object's kind
THE_KIND = ("the {c}", "the one {c}", "that {c}")
KIND_FRAMES = (
    "{P} asked for the one {c}.",
    "{P} wants the {c}.",
    "Give {p} the one {c}, please.",
    "Could you take the {c} to {p}?",
    "The one {c} for {p}.",
    "Can {p} have the {c}?",
    "{P} needs that {c}.",
    "Pass {p} the {c}, would you.",
    "Give {p} the {u}, no, the {c}.",
    "The {u} to {p}, sorry, I mean the one {c}.",
    "Hand {p} the {u}, scratch that, the {c}.",
)
# the speaker's own want joined to an entry: refused (every opener before an entry that opens
# with "For <person>, …" or "To <person>, …")
SPEAKER_OPENERS = (
    "We need the {o}, ",
    "I need the {o}, ",
    "We'd like the {o}, ",
    "The {o} for us, ",
    "Bring me the {o}, and ",
    "I'll take the {o}, ",
)
SPEAKER_CLOSERS = (
    ", and we need the {o}",
    ". We want the {o} as well.",
    ", and the {o} for us",
    ", then bring me the {o}",
)
# words that stand for a person of a gender
_HE_SHE = ("he", "she", "him", "her", "his", "hers", "himself", "herself")
# words that tell a person apart from another of the same title
_GENDERED = frozenset(
    [
        *_HE_SHE,
        "mr",
        "mrs",
        "ms",
        "miss",
        "sir",
        "madam",
        "lady",
        "gentleman",
        "man",
        "woman",
        "boy",
        "girl",
        "grandpa",
        "grandma",
        "granny",
        "grandad",
        "lad",
        "lass",
        "mum",
        "dad",
        "mother",
        "father",
        "son",
        "daughter",
    ]
)
REFERENCE_FORMS = ("kind alone", "title", "frame", "one of a kind", "speaker")
# exclusions (session 27; main read "I hope this is okay, give Alice a mug, just not the blue one.
# Good robot." as either mug and "I know you're busy, but the blocks to Ava, sorry, just the one.
# Have a great day." as both blocks): {c} a kind the scene has several of, {cs} its plural, {x}
# the word that tells one of them apart ("blue"); each form with what it must read as
REST_ANY = (  # a choice of the kind's others
    "Give {p} a {c}, just not the {x} one.",
    "{P} can have a {c}, but not the {x} one.",
    "{P} gets a {c}, just not the {x} {c}.",
    "A {c} for {p}, just not the {x} one.",
)
REST_ALL = (  # every one of the kind's others
    "Give {p} the {cs}, just not the {x} one.",
    "The {cs} to {p}, but not the {x} one.",
    "{P} gets the {cs}, except the {x} one.",
)
ONLY_THAT = (  # the one named ("Both" only where the kind has two)
    "Both {cs} to {p}, sorry, just the {x} one.",
    "The {cs} to {p}, no, only the {x} one.",
    "Give {p} the {cs}, sorry, just the {x} one.",
)
JUST_ONE = (  # which one? refused with the readings
    "The {cs} to {p}, sorry, just the one.",
    "Give {p} the {cs}, sorry, only the one.",
    "Both {cs} to {p}, no, just the one.",
)
EXCLUSION_FORMS = ("rest, any", "rest, all", "only that", "just one", "wrapped")
# a narrowing after a comma in an entry ("…, just not the black one", "…, sorry, just the one")
_NARROWS = re.compile(
    r"(?i),\s*(?:(?:sorry|no|oh|wait|actually),\s*)*(?:just|only|but|except|not|apart)\b"
)
# tails (session 28; main read "Doesn't matter to me if it's Person A or Person B that ends up with
# the chips. Give Person A the bottle." as the chips alone, and "Give Lena the knife and the lemon,
# the lemon first. Also, give Mr Novak the salt shaker." as the three in any order): a sentence
# after an entry that adds a handover of an object the entry does not name (the entry's reading
# kept, that handover read too: "tail adds"), or that must be refused ("tail refused")
TAIL_ADDS = (
    " Also, give {p} the {o}.",
    " And the {o} to {p} as well.",
    " {P} gets the {o} too.",
)
TAIL_REFUSED = (
    " Then I want the {o}.",  # the speaker's own want
    " Hmm, or maybe not.",  # left undecided
    " Ask {p} first.",  # deferred
    " And the thing for the other one.",  # nothing in the scene
)
TAIL_FORMS = ("adds", "refused")
# asides (session 29; blind27 had "For the ghillie's picnic, …", "Sorry, typing this from the cave
# entrance", "the pallets are splintery" and "Carol the crofter wants …", "Person B, the acrobat,
# …"): a remark that names nothing in the scene, before or after an entry, or a trade said after a
# person's name, which must leave the entry's reading as it is (or be refused); only where nothing
# in the remark or the trade names a thing of the scene (``_names_nothing``)
ASIDES_BEFORE = (
    "Sorry, typing this from the car park. ",
    "It's been a long morning. ",
    "For tomorrow's picnic, ",
    "The floor's just been mopped, so mind how you go. ",
    "Bit of a rush today. ",
    "While the kettle boils, ",
    "Sorry about the noise, the builders are in. ",
)
ASIDES_AFTER = (  # (the "," forms only after a sentence that is not a question)
    ". Sorry, typing this from the car park.",
    ". It's been a long morning.",
    ", for tomorrow's picnic.",
    ". The floor's a bit wet, mind.",
    ". Lovely weather today.",
    ", while the kettle boils.",
    ". The builders are in, sorry about the noise.",
)
TRADES = ("baker", "crofter", "plumber", "juggler", "night porter", "acrobat", "locksmith")
ASIDE_FORMS = ("before", "after", "trade")
# afterthoughts (session 30; blind28 had "Give Bob the apple, oh hang on, Alice rather.", "The
# scanner to Mia. Wait, Tom, not Mia.", "Thermometer to Mr Lee, or rather Ruth, she's checking
# temps.", "The bottle to Person A, or Person B maybe, I can't remember which." (refused), "The
# glaciologist, Person A, needs the bottle, she's parched." and "Person A's getting three items:
# bottle, chips, cup"): {q} the person an entry's one handover goes to instead, {p} the person the
# entry named; a form for a question entry must open a sentence (". …")
RECIPIENT_FIXES = (  # the handover to {q}
    ", oh hang on, {q} rather",
    ". Scratch that, {q}.",
    ", no sorry, {q}",
    ", or rather {q}",
    ", beg pardon, to {q}",
    ". Wait, {q}, not {p}.",
    ", sorry, I meant {q}",
    ". Sorry, I meant {q}.",
    # (session 37; blind35's corrections: "hang about, I mean Zoe", "No, correction, they're for
    # Person B", "what am I saying, … Person A gets it")
    ", hang about, I mean {q}",
    ". No, correction, it's for {q}.",
    ", oh dear, it should be {q}",
    ", what am I saying, {q} gets it",
    # (session 38; blind36's corrections restating who wants it: "actually, … it's Person B who's
    # just finished …", "oh, correction, he's wanting the bottle")
    ", actually, it's {q} who asked for it",
    ". Oh, correction, {q} is the one who wants it.",
)
REASONS = (", I mixed them up", ", my mistake", ", long day", ", I got the names muddled")
UNDECIDED = (  # refused: which person is left open
    ", or {q} maybe, I can't remember which",
    ", or was it {q}? I forget.",
    ", no, {q}, or was it {p}...",
    ", unless it was {q}, I'm not sure",
    ". Or {q}, I can't remember which.",
    ", hang about, or was it {q}?",  # (session 37)
)
# a person's state (before or after a grounded entry with no choice): the entry, or refused
STATES = (
    "{P} is parched.",
    "{P} has had a long day.",
    "{P} is starving.",
    "{P} is freezing.",
    "{P} looks worn out.",
    "{P} is thirsty.",
)
# the count of an entry's handovers restated ({n}, {N} at a sentence's start): right, the entry
# (or refused); one off, refused
COUNTS = (
    ". That's {n} {things} in all.",
    ", {n} {things} all told.",
    ". {N} {things}, that's the lot.",
)
_NUMBERS = ("one", "two", "three", "four", "five", "six", "seven")
# words that stand for a person, which a name said beside the entry could change
_PRONOUNS = frozenset([*_HE_SHE, "they", "them", "their", "theirs", "themselves"])
AFTERTHOUGHT_FORMS = ("recipient", "reason", "undecided", "state", "count", "miscount")
# frames (session 31; blind29 had "What Bob really needs right now, after his shift at the
# chandler's, is the crisps.", "The chips are what Person B is hoping for", "Person A fancies the
# bottle, she tells me." and "Alice, our oboist, would like the bottle up on the shelf"): an
# entry's one handover said as a want in a frame (WANT_FRAMES) or as a want the speaker was told of
# (TOLD): that handover, or refused; the same want negated, had already or past (NOT_WANTED):
# refused; a frame after a grounded entry adding a handover of an object it does not name: the
# entry's reading and that handover (as a tail's, see ``kept``); and a person said by a name in an
# entry described after it between commas (APPOSITIONS: "Alice, our oboist, would like …"): as
# the entry, or refused. The frames say "is" whatever the object ("What Bob needs is the chips").
WANT_FRAMES = (
    "What {p} needs is the {o}.",
    "What {p} would really like is the {o}.",
    "It's the {o} that {p} is hoping for.",
    "It's the {o} {p} is after.",
    "The thing {p} needs is the {o}.",
    "What {p}'s been asking for all morning is the {o}.",
    # (session 37; blind35's wants said by a verb of need or longing: "is gasping for that
    # bottle", "'s going to need the work gloves", "'s been craving")
    "{P} is desperate for the {o}.",
    "{P}'s going to need the {o}.",
    "{P} could really use the {o}.",
    "{P} is in need of the {o}.",
    "{P}'s been craving the {o}.",
    # (session 38; blind36's "could do with the bottple", "would love the chips", "'s after the
    # chips", "could murder the chips")
    "{P} could do with the {o}.",
    "{P} would love the {o}.",
    "{P}'s after the {o}.",
    "{P} could murder the {o}.",
)
TOLD = (
    "{P} wants the {o}, I'm told.",
    "I'm told {p} needs the {o}.",
    "{P} would like the {o}, apparently.",
    "{P} fancies the {o}, or so I hear.",
)
NOT_WANTED = (  # refused: no want (negated, had already, past, or given up)
    "What {p} doesn't need is the {o}.",
    "It's the {o} that {p} already has.",
    "What {p} needed yesterday was the {o}.",
    "The last thing {p} wants is the {o}.",
    "It's the {o} that {p} was hoping for, but not any more.",
    "I'm told {p} has the {o} already.",
    "{P} wanted the {o}, apparently, but not now.",
    "{P} has gone off the {o}.",  # (session 37: a want given up, denied or done without)
    "{P} won't be needing the {o}.",
    "{P} could do without the {o}.",
    "{P} doesn't need the {o} any more.",  # (session 38: blind36's "doesn't need … any more")
    "{P}'s had enough of the {o}.",
)
APPOSITIONS = ("our oboist", "the new intern", "my neighbour", "our bassoonist", "a regular here")
# words after a name that an apposition before them would part from it ("Alice, our oboist, too")
_HELD = frozenset(["too", "rather", "instead", "either", "first", "last", "as", "then", "only"])
# (session 38; blind36's "Person B doesn't need the bottle any more, just the cup.", "so the chips,
# not the bottle", "she's gone off fruit"): for an entry's one handover of a one-of-a-kind object,
# another one-of-a-kind object {x} given up for it (INSTEAD): the entry's handover, or refused
INSTEAD = (
    "{P} doesn't need the {x} any more, just the {o}.",
    "Not the {x} for {p}, the {o}.",
    "{P} has gone off the {x}, so the {o} instead.",
    "{P}'s had enough of the {x}, so the {o}, please.",
    "The {o} for {p}, not the {x}.",
)
FRAME_FORMS = ("frame", "told", "not wanted", "frame tail", "apposition", "instead")
# repairs (session 32; blind30 had "Give the bottle to Person, er, Person A, the only one here."
# and "Notebook to Sam, no, to Priya, Sam's got one.", and the lead found "The magazine, er, the
# jug, for Mr Lee." read as both): an object or a person of an entry said after another one and a
# filler or a word of repair ("the cup, er, the chips", "Carol, sorry, Bob"), or a name begun and
# said again ("Person, er, Person A"): the speaker repairs what they said, so it reads as the entry
# (or refused); an object left undecided between two ("the cup or, er, the chips, I forget
# which"): refused; and, for an entry of one task, another object added before its own with "and"
# ("the cup and, er, the chips"): that task of both objects, or refused. {x} is what is said
# first, {o} the entry's own words. A bare filler (FILLERS) is a repair only outside a list: in "the
# cup, er, the chips and the apple" or "Carol, er, Bob or Alice" it may be a list said haltingly
# (a careful person would read three), so there only a word of repair is said (``_in_list``); and
# nothing is said after a negation ("not Jess, uh, no, Kofi" may undo the "not"; ``_NEGATED``).
FILLERS = ("{x}, er, {o}", "{x}, um, {o}")
REPAIRS = (
    *FILLERS,
    "{x}, sorry, {o}",
    "{x}, I mean {o}",
    "{x}, er, I mean {o}",
    "{x}, no, sorry, {o}",
    "{x}, uh, no, {o}",
)
UNDECIDED_REPAIRS = (  # refused: which object is left open
    "{x} or, er, {o}, I forget which",
    "{x}, or maybe {o}, I can't remember which",
    "{x}, um, or {o}, not sure which",
)
ADDED_REPAIRS = ("{x} and, er, {o}", "{x}, oh, and {o}", "{x} and, um, {o}")
STUTTERS = ("{x}, er, {o}", "{x}, um, {o}", "{x}... {o}")
REPAIR_FORMS = ("object", "undecided", "added", "person", "stutter")
_LIST_BEFORE = re.compile(r"(?i)(?:,|\band|\bor|&)\s*$")
_LIST_AFTER = re.compile(r"(?i)^\s*(?:,\s*(?:the\b|[A-Z])|and\b|or\b|&|plus\b|nor\b)")
_NEGATED = re.compile(r"(?i)\b(?:not|no|except|but|than|nor|without|bar|from)\s+$")
# deferrals (session 33; blind31 read "Bottle to Person A. Chips to Person B. Then whatever the
# deckhand tells you." as the two handovers, its last sentence dropped): words after an entry, or
# before it, that hand part of the decision to someone else or leave it open ("Then whatever the
# deckhand tells you.", "After that, ask Sam what's next.", "The rest is up to Sam.", "…, and see
# what Sam says.", "Check with Sam first."): the plan would be incomplete, or wait on a word the
# robot does not hear, so refused; and a near tail that only closes the request ("Then you're
# done.", "That's all for now."): the entry, or refused. {p} is a person of the scene by a name, or
# a role that names nothing in the scene ("the deckhand"); {o} an object the entry does not name.
ROLES = ("deckhand", "supervisor", "foreman", "shift manager", "site boss", "duty officer")
DEFERRED_AFTER = (  # a sentence after the entry: refused
    " Then whatever {p} tells you.",
    " After that, ask {p} what's next.",
    " The rest is up to {p}.",
    " Then do whatever {p} says.",
    " {P} will tell you what to do after that.",
    " Then ask {p} what to do with the {o}.",
    " And give {p} whatever they ask for.",
    " What comes next is {p}'s call.",
)
DEFERRED_JOINED = (  # a clause joined to the entry (not after a question): refused
    ", and see what {p} says.",
    ", then wait for {p} to tell you what's next.",
    ", and after that it's up to {p}.",
)
DEFERRED_BEFORE = (  # said before the entry: refused
    "Check with {p} first. ",
    "Once {p} says so, ",
    "Depending on what {p} says, ",
    "Wait for {p} to give the word, then ",
    "Ask {p} before you start. ",
)
SETTLED = (  # a near tail that only closes the request: the entry
    " Then you're done.",
    " That's all for now.",
    " That's everything.",
    " Nothing else after that.",
    " That's it, thanks.",
    " After that, you're free.",
)
# (session 34) "… is up to you": the robot is "you", so a choice left up to it is a free choice
# and no deferral (blind32's "One for Person A, one for Person B, …; who gets which is up to you."
# was refused by the first deferral rule): an entry with a choice in it, with a clause or sentence
# leaving the choice to the robot (YOURS_JOINED, YOURS_AFTER): the entry; and, after a grounded
# entry with no choice or order in it, a sentence adding a choice of two objects for a person left
# to the robot (YOURS_ADDED): the entry and that choice.
YOURS_JOINED = (", it's up to you.", ", up to you.", ", your choice.", ", whichever you like.")
YOURS_AFTER = (
    " It's up to you which.",
    " The choice is up to you.",
    " Up to you.",
    " Which one is up to you.",
)
YOURS_ADDED = (
    " Also, give {p} the {o} or the {x}, it's up to you which.",
    " And {p} gets the {o} or the {x}, whichever you like.",
)
DEFERRAL_FORMS = ("after", "joined", "before", "settled", "yours", "yours added")
# clefts (session 34; blind32 had "What Person A wants is the bottle"-like wants and clefts the
# ten families did not say): an entry's one handover of a one-of-a-kind object to a person said as
# a pseudo-cleft or an it-cleft (CLEFTS: "It's Bob who gets the chips.", "The chips are what Bob's
# after."): that handover, or refused; with another person set against the one named inside or
# after it (CONTRASTS: "It's Bob, not Alice, who gets the chips."): the same handover; negated
# (NOT_CLEFTS: "It's not Bob who gets the chips."): refused, it names no recipient (in a scene of
# two, a careful reader would not guess the other one either); said of a person the scene does not
# have (ABSENT, by CLEFTS: "It's Zoe who gets the chips."): refused; with a second one-of-a-kind
# object (SECOND: "It's Bob who gets the chips and the apple."): both handovers, never the entry's
# one alone; and a cleft after a grounded entry adding a handover of an object it does not name
# (the entry's reading and that handover, as a tail's, see ``kept``). For an entry of one placement
# of a one-of-a-kind object: the surface said in a cleft (PLACE_CLEFTS: "The shelf is where the
# apple goes."): that placement, or refused. {be} agrees with the object ("The chips are …").
CLEFTS = (
    "What {p} wants is the {o}.",
    "It's {p} who gets the {o}.",
    "The {o} {be} what {p}'s after.",
    "{P} is the one to have the {o}.",
    "{P} is the one who gets the {o}.",
    "The one who gets the {o} is {p}.",
    "It's {p} that the {o} {be} for.",
    "The {o} {be} what {p} wants.",
    "It's {p} the {o} {go} to.",
)
CONTRASTS = (  # {q} another person of the scene: the handover to {p}
    "It's {p}, not {q}, who gets the {o}.",
    "It's {p} who gets the {o}, not {q}.",
    "{P}, not {q}, is the one to have the {o}.",
    "The {o} {be} for {p}, not for {q}.",
    # (session 38; blind36's "Person A shouldn't get the chips; they're for Person B.", "The banana
    # isn't for Omar, it's Emma who's asked for it.")
    "{q} shouldn't get the {o}; {p} should.",
    "Not {q}, it's {p} who gets the {o}.",
    "The {o} {be} not for {q}, it's {p} who asked for {it}.",
)
NOT_CLEFTS = (  # refused: no recipient named
    "It's not {p} who gets the {o}.",
    "It isn't {p} who wants the {o}.",
    "{P} isn't the one to have the {o}.",
    "What {p} wants isn't the {o}.",
    "It's not {p} that the {o} {be} for.",
)
ABSENT = ("Zoe", "Mr Okafor", "Priyanka", "Dr Hale", "Nikos", "Grandma Rose")
SECOND = (  # the handover of both objects
    "What {p} wants is the {o} and the {x}.",
    "It's {p} who gets the {o} and the {x}.",
    "The {o} and the {x} are what {p}'s after.",
    "{P} is the one to have the {o} and the {x}.",
)
CLEFT_TAILS = (  # after a grounded entry: that handover too
    " And it's {p} who gets the {o}.",
    " Also, what {p} wants is the {o}.",
    " The {o} {be} what {p}'s after, too.",
)
PLACE_CLEFTS = ("The {s} is where the {o} goes.", "Where the {o} goes is the {s}.")
CLEFT_FORMS = ("cleft", "contrast", "not", "absent", "second", "cleft tail", "place")
# counts (session 35; the issue's "counts and plurals that must match the scene"): a kind the
# scene has several objects of said with a count or a quantifier for a person (KIND_COUNTS: "Give
# Bob the two mugs.", "Give Bob all three pens."; BOTH: "Give Bob both mugs."): every one of the
# kind to that person where the count agrees with the scene; refused where it does not ("the three
# mugs" of two, "both pens" of three: a careful person asks which, or what is missing). An entry's
# one one-of-a-kind object said as the only one (ONE: "the one apple", "the only apple"): the
# entry; said as several (SEVERAL: "both apples", "the two apples"): refused. An entry's kind in
# the plural ("the mugs", every one of the kind) said with its count or "both" (the entry) or with
# another count (refused). "all {n}" is said for three or more only ("all two mugs" is no English).
NUMBERS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")
KIND_COUNTS = (
    "Give {p} the {n} {cs}.",
    "{P} gets the {n} {cs}.",
    "The {n} {cs} go to {p}, please.",
    "Could you bring {p} the {n} {cs}?",
    "Give {p} all {n} {cs}.",
)
BOTH = (
    "Give {p} both {cs}.",
    "Both {cs} to {p}, please.",
    "{P} gets both {cs}.",
    # (session 37; blind35's "The pair of cups, the green and the white, …": "the pair of" is
    # "both", and of three a careful person asks which two)
    "Give {p} the pair of {cs}.",
    "The pair of {cs} go to {p}.",
)
ENTRY_COUNTS = ("the {n} {cs}", "all {n} {cs}")  # an entry's "the <kinds>" said with a count
ENTRY_BOTH = ("both {cs}", "the pair of {cs}")  # … and said as two
ONE = ("the one {o}", "the only {o}", "the single {o}")
SEVERAL = ("both {os}", "the two {os}", "all three {os}", "the 2 {os}")
MASS = frozenset(["glue", "salt", "tape", "water", "juice", "milk", "rice", "soup", "sugar"])
# (session 38; blind36's "any old mug will do her", "any of the pens will do", "either will do",
# "whichever's nearer"): one of a kind the scene has several of for a person, any one (ANY_OF): a
# choice of each of the kind to that person, or refused
ANY_OF = (
    "Give {p} any of the {cs}, whichever's nearer.",
    "{P} can have one of the {cs}, any will do.",
    "Any {c} will do for {p}.",
    "One of the {cs} for {p}, doesn't matter which.",
    "{P} isn't fussy, any {c} will do.",
)
COUNT_FORMS = ("kind", "kind miscounted", "one", "several", "entry", "entry miscounted", "any")
# remarks (session 36; blind34 had "she's frozen, the heating's off on this side", "rough poker
# night" and "the whole lot's for the same van" among its refusals): a remark after an entry that
# names no object, person or surface of the scene and carries no request, negation, time or
# condition (REMARKS: the entry, or refused; a refused entry stays refused with its readings); a
# remark that says the one person an entry hands its one object to does not want it (CONTRARY:
# refused, a careful person asks); and a delay after an entry (TIMED: refused, doing it now does not
# wait for it, as docs/grounding.md's "what it is for, and by when" has it). After a question only
# the ". " forms, each a sentence of its own. No "but" or "though" before CONTRARY's remark: a
# concession ("…, though Bob said not to bother": do it anyway) is a reading a careful person may
# take, so it would be no clear refusal.
REMARKS = (
    ", the heating's off",
    ", it's for the bake sale",
    ", it's been one of those days",
    ", the lift's out again",
    ", we're a bit short-staffed",
    ", I've got my hands full",
    ". The heating's off.",
    ". It's for the bake sale.",
    ". We're a bit short-staffed today.",
    # (session 37; blind35's speaker saying who they are: "I'm off to my shift as a shunter", "I'm
    # the philatelist and …")
    ", I'm the relief cook today",
    ". I'm new on this shift.",
    ", I'm a night porter by trade",
)
CONTRARY = (  # {p} the entry's one person as it says them ({P}: at a sentence's start)
    ", {p} doesn't want it",
    ", {p} said no to it",
    ". {P} doesn't want it.",
    ". {P} said no to it.",
)
TIMED = (
    ", after lunch",
    ", but not until after lunch",
    ", first thing tomorrow",
    ", once the meeting's over",
    ", when I get back from the shops",
    ". Not until this afternoon, though.",
    ". But only once the meeting's over.",
)
# (session 37; blind35's remarks about a person: "he's a roughneck on leave", "She's just back
# from crabbing.", "Emma's only here for the afternoon as a visitor"): a remark about a person of
# the scene said by a name, after a grounded entry with no pronoun for a person (a name said beside
# a pronoun could change whom it means): the entry, or refused
CONTEXT = (
    ", {p}'s just back from the gym",
    ", {p}'s had a long shift",
    ", {p} is new here",
    ", {p}'s a new starter",
    ". {P}'s just back from the gym.",
    ". {P} has been on the phone all morning.",
    ". {P} is new on the team.",
)
# (session 38; blind36's "carols back from the glass blowers so the red mug to her …"): the same
# remarks said before the entry, joined by "so" or a sentence of their own: the entry, or refused
CONTEXT_BEFORE = (
    "{P}'s just back from the gym, so ",
    "{P}'s had a long shift, so ",
    "{P} is new here, so ",
    "{P} has been on the phone all morning. ",
)
# (session 38; blind36's remarks about the person by a pronoun: "shes back from her jenga
# tournament", "the pony club tired him out", "hes been out with the tree fellers all day"): after
# an entry of one handover naming its one person by a name and no other person or object (and no
# pronoun for a person), a remark about a person by a pronoun (PRONOUN_SETS fill {s} "she's", {h}
# "she's"/"they've", {pos} "her", {obj} "her"; {S}, {H}, {Pos} at a sentence's start): the entry,
# or refused (whomever the pronoun means, the remark asks for nothing)
ABOUT = (
    ", {s} just back from {pos} pottery class",
    ", {h} been out on the allotment all day",
    ", the choir practice wore {obj} out",
    "; {pos} shift was a long one",
    ". {S} just back from {pos} pottery class.",
    ". {H} been on {pos} feet all morning.",
    ". The quiz night tired {obj} out.",
)
PRONOUN_SETS = (
    {"s": "he's", "h": "he's", "pos": "his", "obj": "him"},
    {"s": "she's", "h": "she's", "pos": "her", "obj": "her"},
    {"s": "they're", "h": "they've", "pos": "their", "obj": "them"},
)
REMARK_FORMS = ("remark", "time", "contrary", "context", "about", "context before")
# (session 39; blind37's closing remarks, about half its refusals: "he's late for the cake stall",
# "her decoupage glue's drying", "we've the van hire place shutting at noon", "the lights have gone
# out in the back"; said here by subjects and in places blind37 and the forms above do not use, so
# that a rule for the kind is measured on forms it was not written on). Each asks nothing, names
# nothing of the scene (a form that would is left out), holds no time that defers, no want, no
# negation and no word that points back: the entry, or refused (a refused entry stays refused,
# with its readings). By a pronoun before an entry of one handover naming its one person
# (ABOUT_BEFORE; PRONOUN_SETS fill it as ABOUT); by a possessive, "his"/"her"/"their", after such an
# entry (POSSESSIVE), or a person's name and "'s" after a grounded entry with no pronoun for a
# person (POSSESSIVE_NAMED); by "we" (WE, WE_BEFORE) or about the place (PLACE, PLACE_BEFORE) after
# or before any entry; as a sentence between two sentences of an entry saying no word that points
# back and taking nothing back (MIDDLE); and as a clause "who …" after a name of a person inside a
# grounded entry with no pronoun for a person (WHO; "Give Bob, who's new here, the apple.").
ABOUT_BEFORE = (
    "{H} been on the door at the beer festival, so ",
    "{S} back from {pos} shift at the sorting office. ",
    "{H} had a morning of it at the allotments, so ",
    "{H} got a train to catch, so ",
)
POSSESSIVE = (
    ", {pos} bus is running late",
    ", {pos} knee's playing up again",
    "; {pos} sister's visiting from Leeds",
    ". {Pos} van's stuck behind a tractor.",
    ". {Pos} back has been bad all week.",
)
POSSESSIVE_NAMED = (
    ", {p}'s knee is playing up again",
    ", {p}'s bus was late",
    ". {P}'s van is stuck behind a tractor.",
)
WE = (
    ", we've got the inspectors in",
    ", we're rushed off our feet",
    ", we've a coach party coming",
    ". We're hosting the darts league.",
    ". We've the auditors in.",
)
WE_BEFORE = (
    "We're rushed off our feet, so ",
    "We've got the inspectors in. ",
    "We've a coach party coming, so ",
)
PLACE = (
    ", the car park's flooded again",
    ", the back door's jammed",
    ", the boiler's playing up",
    ". The fire alarm's being tested.",
    ". The wifi's down again.",
)
PLACE_BEFORE = (
    "The car park's flooded again, so ",
    "The back door's jammed. ",
    "The wifi's down, so ",
)
MIDDLE = (
    "The boiler's playing up again.",
    "We're rushed off our feet.",
    "The car park's flooded.",
    "{P} has been on the tills all day.",
    "{P}'s bus was late.",
)
WHO = (
    ", who's new here,",
    ", who's just back from the gym,",
    ", who has had a long shift,",
    ", who's been on the tills all day,",
)
REMARK_FORMS39 = (
    "about before",
    "possessive",
    "possessive by name",
    "we",
    "we before",
    "place",
    "place before",
    "middle",
    "who",
)
# purposes (session 40; blind38's purpose "for <an event, a pastime, an outing>" beside a request:
# "Carol's after a red mug for her ham radio night", "wants the chips for the bar billiards
# league", "The bottle? Person A, for the seed swap."; said here with events, pastimes and groups
# no earlier part uses, so that a rule for the kind is measured on forms it was not written on).
# Each names nothing of the scene (a form that would is left out). A purpose beside a request that
# has its recipient or place changes nothing: the entry, or refused (a refused entry stays refused
# with its readings); said after it with or without a comma (PURPOSE_AFTER: at its end, before a
# question mark; without a comma only after a name of the scene), before it ("For the harvest
# supper, …"), after its one object inside it ("Give the apple for the cricket tea to Bob."), as a
# sentence after it (PURPOSE_SENTENCES), and as "his/her/their <pastime>" after an entry of one
# handover naming its one person, the possessive fitting that person (PURPOSE_OWN; "his"/"her"
# only of a name NAMED_HE/NAMED_SHE says). Refused: the purpose as the only recipient of an
# object (PURPOSE_ONLY: "The apple for the ramblers."), and the request said after it to be for a
# later time (PURPOSE_TIMES: ", it's for tonight"; a bare "for tonight" after the objects is what
# the thing is for, read by decided rules, and is not made). A possessive fitting another person
# of the scene and not the one named ("Give Bob the apple for her wild swim."): the entry, or
# refused (`possessive other`; the handover is said whole, the possessive says whose the event is).
PURPOSE_EVENTS = (
    "the harvest supper",
    "the open mic night",
    "the litter pick",
    "the cricket tea",
    "the flower show",
    "the treasure hunt",
    "the lantern parade",
    "the ghost walk",
    "the stamp fair",
    "the vintage tractor run",
)
PURPOSE_GROUPS = (
    "the ramblers",
    "the quilters",
    "the pigeon fanciers",
    "the cub pack",
    "the litter pickers",
    "the clog dancers",
    "the wassail committee",
)
PURPOSE_OWN = (  # after "his" / "her" / "their"
    "evening class",
    "first aid course",
    "wild swim",
    "fell run",
    "folk night",
    "rock pooling trip",
    "mah jong night",
    "bell ringing practice",
)
PURPOSE_SENTENCES = (". That's for {x}.", ". It's all for {x}.")
PURPOSE_ONLY = (  # {o} a one-of-a-kind object ({O} at a sentence's start), {x} a purpose
    "The {o} for {x}.",
    "{O} for {x}, please.",
    "Could you hand over the {o} for {x}?",
    "The {o}'s for {x}.",
    "Take the {o} over for {x}.",
)
PURPOSE_TIMES = (
    ", it's for tonight",
    ", that's for after lunch",
    ", that one's for tomorrow",
    ", it's for after the meeting",
    ". It'll be for this evening.",
    ". That's for later.",
)
# names of the scenes whose people a careful reader takes for a man or a woman ("his"/"her")
NAMED_HE = frozenset(
    ["Bob", "Kofi", "Marco", "Grandad", "Mr Lee", "Noah", "Omar", "Tom", "Mr Novak"]
)
NAMED_SHE = frozenset(
    [
        *("Alice", "Carol", "Dana", "Lily", "Mia", "Mrs Ortiz", "Priya", "Ruth", "Lena", "Jess"),
        *("Ava", "Emma", "Mrs Khan", "Zoe"),
    ]
)
PURPOSE_FORMS = (
    "after",
    "after comma",
    "before",
    "inside",
    "sentence",
    "possessive",
    "possessive other",
    "only",
    "time",
)
# idioms (session 41; blind39's refusals were want idioms "would be glad of", "'s gasping for",
# choice idioms "your call", "whichever's free", "a drink apiece" and exclusions "bar the mugs",
# "rather than P"; 12 and 12r write rules for these kinds this session). So that a rule for a kind
# is measured on forms it was not written on, the family says the kinds by idioms blind39 does not
# use, over grounded entries (a request that reads), each with the verdict it must get; a refusal
# is always allowed. A want idiom of the entry's one handover of a one-of-a-kind object to a person
# (WANT_IDIOMS, `want`): that handover; after a grounded entry for a one-of-a-kind object it does
# not name (`want tail`): the entry's reading and that handover (as a tail's, see ``kept``). An
# idiom that takes the want back (CANCELLED: "can do without", "has gone off", "is so over", a want
# that has passed) said alone (`cancelled`) or after the entry of that handover (`cancelled after`:
# the entry said and then unsaid): refused. A choice left to the robot (CHOICE_IDIOMS) between two
# one-of-a-kind objects for a person (`choice`), between the objects of a kind the scene has
# several of (CHOICE_KIND: `choice kind`) and between two people for the entry's object
# (CHOICE_PERSON: `choice person`): that choice; a choice of a kind the scene lacks (CHOICE_ABSENT
# with ABSENT_KINDS: `choice absent`): refused. An exclusion idiom of one of a kind the scene tells
# apart (EXCLUSION with {x} its word: `exclusion`): every other one of the kind; and of one object
# from everything in the scene (EXCLUSION_ALL: `exclusion all`): every other object of the scene
# to the person.
WANT_IDIOMS = (
    "{P} fancies the {o}.",
    "{P} is dying for the {o}.",
    "{P} has a hankering for the {o}.",
    "{P} has a yen for the {o}.",
    "{P} is crying out for the {o}.",
    "{P} is longing for the {o}.",
    "{P} is itching to get hold of the {o}.",
    "{P} would give anything for the {o}.",
    "{P} wouldn't say no to the {o}.",
    "{P} is in the market for the {o}.",
    "{P} would be grateful for the {o}.",
    "{P} is angling for the {o}.",
    "{P} is hankering after the {o}.",
    "{P} is on the lookout for the {o}.",
    "{P} would jump at the {o}.",
    "The {o} would make {p}'s day.",
)
CANCELLED = (  # refused: the want taken back, given up, had already, or passed
    "{P} can do without the {o}.",
    "{P} has gone off the {o}.",
    "{P} has no use for the {o}.",
    "{P} has lost interest in the {o}.",
    "{P} can live without the {o}.",
    "{P} is fed up with the {o}.",
    "{P} has finished with the {o}.",
    "{P} is so over the {o}.",
    "{P} has gone cold on the {o}.",
    "{P} was dying for the {o}, but not any more.",
    "{P} had a hankering for the {o}, but it's passed.",
    "{P} wouldn't thank you for the {o}.",
    "{P} is through with the {o}.",
    "{P} doesn't fancy the {o}.",
    "{P} has already got the {o}.",
)
CHOICE_IDIOMS = (  # {o}, {x} two one-of-a-kind objects, {p} a person
    "Give {p} the {o} or the {x}, take your pick.",
    "Take your pick: the {o} or the {x} for {p}.",
    "{P} gets the {o} or the {x}, suit yourself which.",
    "The {o} or the {x} for {p}, whichever takes your fancy.",
    "The {o} or the {x} to {p}, I'll leave it with you.",
    "Give {p} the {o} or the {x}, dealer's choice.",
    "Hand {p} the {o} or the {x}, I'm not fussed which.",
    "The {o} or the {x} for {p}, it's your shout.",
    "Either the {o} or the {x} for {p}, as you see fit.",
)
CHOICE_KIND = (  # {c} a kind the scene has several of, {cs} its plural
    "Give {p} whichever {c} you like.",
    "{P} gets a {c}, take your pick.",
    "Any {c} you fancy for {p}.",
    "A {c} for {p}, suit yourself which.",
    "Pick out one of the {cs} for {p}, any you like.",
    "{P} can have a {c}, I'll leave the choice to you.",
)
CHOICE_PERSON = (  # {q} another person of the scene
    "Give the {o} to {p} or {q}, take your pick.",
    "The {o} goes to {p} or {q}, suit yourself which.",
    "{P} or {q} can have the {o}, whoever you like.",
    "Hand the {o} to {p} or {q}, your pick.",
)
CHOICE_ABSENT = (  # {a} a kind the scene has none of, {plural} its plural: refused
    "Give {p} whichever {a} you like.",
    "Take your pick of the {plural} for {p}.",
    "{P} gets one of the {plural}, suit yourself which.",
)
ABSENT_KINDS = ("umbrella", "teapot", "stapler", "ladle", "torch", "kazoo", "colander")
EXCLUSION = (  # {x} the word telling one of the kind apart: every other one of the kind
    "Give {p} all the {cs} but the {x} one.",
    "Give {p} the {cs}, all but the {x} one.",
    "Every {c} save the {x} one to {p}.",
    "The {cs} to {p}, minus the {x} one.",
    "{P} gets the {cs}, leaving out the {x} one.",
    "Give {p} the {cs}, the {x} one excepted.",
    "Give {p} the {cs}, not counting the {x} one.",
    "Give {p} the {cs}, with the exception of the {x} one.",
    "All the {cs} to {p} other than the {x} one.",
)
EXCLUSION_ALL = (  # {o} a one-of-a-kind object: every other object of the scene
    "Give {p} everything but the {o}.",
    "{P} gets the lot, save the {o}.",
    "{P} can have the whole lot apart from the {o}.",
    "Everything for {p}, hold the {o}.",
    "Give {p} the lot minus the {o}.",
    "{P} gets everything, leave out the {o}.",
)
IDIOM_FORMS = (
    "want",
    "cancelled",
    "cancelled after",
    "choice person",
    "want tail",
    "choice",
    "choice kind",
    "choice absent",
    "exclusion",
    "exclusion all",
)
# turns (session 42; blind40's refusals were negations and exclusions, corrections and courtesy
# question forms: 20, 13 and 15 of its 113 misses; this session's tuners write rules for these
# kinds). So that a rule for a kind is measured on forms it was not written on, the family says
# a grounded entry's request (or, for the forms that need none, a request of the scene) by idioms
# of the three kinds blind40 does not use, each with the verdict it must get; a refusal is always
# allowed. (a) Negation and exclusion: for an entry of one handover of a one-of-a-kind object {o}
# to a person {p}, another object {x} said not to be for that person before the handover
# (NOT_FOR, `not for`), not needed beside it (NEED_INSTEAD, `need instead`), two others said
# neither of them (NEITHER, `neither`), and another person {q} said not to be the one (NOT_THEIRS,
# `not theirs`): that handover; every object but one from everything (EVERYTHING_BUT, `everything
# but`): every other object of the scene; the one of a kind of two that is not the one named
# (THE_OTHER, `the other`): that one; and refused: every one of a kind left out (EXCLUDED_ALL,
# `nothing left`) and "the <kind> that isn't the <x> one" of a kind of three or more (THE_OTHER,
# `several left`; with the rest as readings). (b) Corrections, after an entry of one handover
# naming no other object: the object corrected (OBJECT_FIXED, `object fixed`; the handover of
# {x}), the person corrected where the entry names no other person (PERSON_FIXED, `person
# fixed`; the handover to {q}); and refused: a second object that could replace the entry's or
# be added to it (REPLACE_OR_ADD, `replace or add`; both objects as readings) and a correction to
# a kind the scene lacks (FIXED_ABSENT, `fixed absent`: the entry's object was taken back).
# (c) Courtesy and question forms: an entry that is one request from its verb ({v}, lower case,
# without its stop) asked as a courtesy (COURTESIES, `courtesy`): the entry; for an entry of one
# handover, that handover proposed as a question and then agreed to (PROPOSALS, `proposal`): the
# handover; proposed and then dropped (PROPOSALS_DROPPED, `proposal dropped`) and a question that
# only asks whether (WHETHER, `whether`): refused. And one variant of an entry that must read, said
# all in lower case (`lower`), and one with two letters swapped inside a word of five letters or
# more naming nothing of the scene (`typo`; blind40 said 13 of its misses in lower case, 7 with a
# typo): as it must.
NOT_FOR = (  # {x} another one-of-a-kind object: the handover of {o} to {p}
    "The {x} isn't meant for {p}. {P} should get the {o}.",
    "{P} isn't to have the {x}; hand {p} the {o}.",
    "Not the {x}, {p} gets the {o}.",
    "Leave the {x} out of it; the {o} goes to {p}.",
    "The {x} is no good for {p}; give {p} the {o}.",
    "Forget about the {x} for {p}. Give {p} the {o}.",
)
NEED_INSTEAD = (
    "{P} has no need of the {x}; give {p} the {o}.",
    "{P} won't be needing the {x}; the {o} is what {p} needs.",
    "{P} doesn't want the {x} after all, just the {o}.",
    "{P} can manage without the {x} but needs the {o}.",
    "Rather than the {x}, {p} needs the {o}.",
    "{P} is all right for the {x}, but could use the {o}.",
)
NEITHER = (  # {x}, {y} two other one-of-a-kind objects
    "Neither the {x} nor the {y}; the {o} for {p}.",
    "Not the {x}, not the {y}: give {p} the {o}.",
    "{P} wants neither the {x} nor the {y}, just the {o}.",
    "No {x}, no {y}, just the {o} for {p}.",
    "Don't give {p} the {x} or the {y}; give {p} the {o}.",
)
NOT_THEIRS = (  # {q} another person of the scene
    "The {o} is meant for {p}, not {q}.",
    "Don't give {q} the {o}; {p} gets it.",
    "{Q}'s not getting the {o}, {p} is.",
    "The {o} isn't {q}'s to take, it's for {p}.",
    "Not {q}: the {o} goes to {p}.",
    "It's not {q} but {p} who should have the {o}.",
)
EVERYTHING_BUT = (  # every other object of the scene to {p}
    "Give {p} everything except the {o}.",
    "Give {p} the lot, excluding the {o}.",
    "{P} gets all of it, the {o} aside.",
    "Give {p} everything barring the {o}.",
    "Everything but the {o} is for {p}.",
    "Everything for {p}, only not the {o}.",
    "Everything besides the {o} to {p}.",
    "Hand {p} the entire lot except for the {o}.",
)
THE_OTHER = (  # {c} a kind, {x} the word telling one of it apart: the other one, if one is left
    "Give {p} the {c} that isn't the {x} one.",
    "The {c} other than the {x} one goes to {p}.",
    "{P} should get the {c} that's not the {x} one.",
    "Hand {p} the {c} which isn't {x}.",
)
EXCLUDED_ALL = (  # {xs} every one of the kind by its word ("the red one and the blue one")
    "Give {p} the {cs}, except {xs}.",
    "All the {cs} to {p} apart from {xs}.",
    "Every {c} for {p} but {xs}.",
)
OBJECT_FIXED = (  # after the entry without its stop: the handover of {x} to the entry's person
    ". Wait, I misspoke: the {x}.",
    ". Correction: make that the {x}.",
    ". My mistake, I meant the {x}.",
    ", well, the {x} actually.",
    ". Let me rephrase: the {x}.",
    ", no, hang on, the {x}.",
    ". Sorry, wrong one: the {x}.",
    ". Ah, not that one, the {x}.",
    ". Oops, I meant to say the {x}.",
    ". Tongue slipped there, it's the {x}.",
)
PERSON_FIXED = (  # {q} another person: the handover to {q}
    ". Make that {q}.",
    ", {q} I should say.",
    ". Ah no, {q}'s the one, not {p}.",
    ". I misspoke, it's {q}.",
    ". Oops, wrong name: {q}.",
    ". Did I say {p}? I meant {q}.",
)
REPLACE_OR_ADD = (  # refused: {x} could replace the entry's object or be added to it
    ". Oh, and the {x}, or instead, I forget which.",
    ". The {x} as well, or in its place, I can't remember.",
    ". And the {x}, sorry, or was that instead?",
    ", plus or instead the {x}, not sure which.",
)
FIXED_ABSENT = (  # refused: corrected to {a}, a kind the scene lacks
    ". My mistake, I meant the {a}.",
    ". Correction: make that the {a}.",
    ", no, hang on, the {a}.",
    ". Wait, I misspoke: the {a}.",
)
COURTESIES = (  # {v} the entry's request from its verb, lower case, without its stop
    "Might I ask you to {v}?",
    "Any chance you could {v}?",
    "Be a dear and {v}.",
    "Do me a favour and {v}, would you?",
    "I don't suppose you could {v}?",
    "Would you be so good as to {v}?",
    "If it's no trouble, could you {v}?",
    "Would you do the honours and {v}?",
    "Could I impose on you to {v}?",
    "Would it be a nuisance to ask you to {v}?",
    "Would you kindly {v}?",
    "Sorry to be a pain, but could you {v}?",
)
PROPOSALS = (  # the handover of {o} to {p} proposed, then agreed to
    "What do you say to {p} having the {o}? Go ahead.",
    "Why not give {p} the {o}? Yes, go on.",
    "Should {p} get the {o}, do you reckon? Yes, go on then.",
    "Suppose {p} had the {o}? Right, do that.",
    "What about the {o} for {p}? Yes, let's go with that.",
    "Would it work if {p} had the {o}? Good, do it.",
)
PROPOSALS_DROPPED = (  # refused: proposed, then dropped
    "What do you say to {p} having the {o}? Actually, no.",
    "Why not give {p} the {o}? No, on second thoughts, leave it.",
    "Should {p} get the {o}, do you reckon? Hmm, maybe not.",
    "Suppose {p} had the {o}? No, scrap that idea.",
)
WHETHER = (  # refused: a question that only asks whether
    "Does {p} still want the {o}?",
    "Have you given {p} the {o} yet?",
    "Would {p} like the {o}, do you think?",
    "Do you know if {p} needs the {o}?",
    "Is the {o} for {p}, do you know?",
    "Did {p} ever get the {o}?",
    "Could {p} use the {o}, I wonder?",
    "Is it true {p} asked for the {o}?",
)
_IMPERATIVE = frozenset(
    ["give", "hand", "pass", "bring", "take", "put", "place", "set", "fetch", "get", "deliver"]
)
TURN_FORMS = (
    "not for",
    "need instead",
    "neither",
    "not theirs",
    "everything but",
    "the other",
    "several left",
    "nothing left",
    "object fixed",
    "person fixed",
    "replace or add",
    "fixed absent",
    "courtesy",
    "proposal",
    "proposal dropped",
    "whether",
    "lower",
    "typo",
)
# said (session 43; blind41's refusals were, among others, want idioms, counts and distributions and
# pronouns and possessives: 13, 16 and 13 of its 98 misses, many of them a request framed around the
# person's reason or state; this session's tuners write rules for these kinds). So that a rule for a
# kind is measured on forms it was not written on, the family says a request the way people frame
# it, by words of its own (none of blind41's), each with the verdict it must get; a refusal is
# always allowed. (a) For an entry of one handover to a person {p}: a reason or state of that person
# said before it, a sentence of its own or joined by "so" (REASONS_BEFORE, `reason before`): the
# entry; and, of a one-of-a-kind object {o}, that handover hung on a condition about others' claims
# ("If nobody's bagsied the {o}, …"; CONDITIONS, `condition`): the handover (the cell hears every
# claim, since they are the requests it is given: the condition is the speaker's hedge; the lead's
# decision of 08:20), and hung on an outside event or a later word ("If it stops raining, …", "… if
# the supervisor says so."; CONDITIONS_OUTSIDE, `condition outside`): refused. (b) That handover
# said as a want by a comparison or a hyperbole (HYPERBOLES, `hyperbole`: "{P} would walk over hot
# coals for the {o}.", "The {o} would be just the ticket for {p}."): the handover; such a want said
# against ("{P} wouldn't be seen dead with the {o}."; HYPERBOLES_AGAINST, `hyperbole against`):
# refused. (c) A distribution of a kind the scene has several of ({c}, {cs}) among people ({ps}:
# "Alice and Bob", "Alice, Bob and Carol") said with 'apiece' / 'each' (APIECE, `apiece`): each of
# them one of the kind, a different one each (every way it can be done, as a choice); said as "one
# for {p} and one for {q}" where the kind has as many as there are people (ONE_FOR, `one for`): the
# same; two one-of-a-kind objects {x}, {y} to two people 'respectively' (RESPECTIVELY,
# `respectively`): {x} to the first, {y} to the second; and refused, a distribution the scene cannot
# satisfy: more people than the kind has objects, or a one-of-a-kind object to each of two (APIECE,
# `apiece short`), three objects to two people 'respectively' (RESPECTIVELY_THREE, `respectively
# short`). (d) An owner said by a possessive or a clause: a one-of-a-kind object back to its owner
# (OWNER_BACK, `owner`: "Take {p}'s {o} back to {them}.", "The {o} {p} had earlier goes back to
# {them}."; {them} "him" / "her" where the name says which, else the name): that handover; someone
# else's object to a person (OWNER_OTHER, `owner other`: "Take {q}'s {o} over to {p}."): the
# handover to {p}; and an owner that could be either of two people (OWNER_EITHER, `owner either`:
# "The {o} is {p}'s or {q}'s, I forget which; take it back to its owner."): refused, both people as
# readings. Then one variant that must read said all in lower case (`lower`) and one with a typo
# (`typo`; as the turns family's): as it must.
REASONS_BEFORE = (  # {P} the entry's one person, before the entry ("so": joined, lower case)
    "{P} has been bell-ringing all evening, so ",
    "{P}'s been on the go since six, so ",
    "After a double shift, {p} is flagging, so ",
    "{P} has had a rotten week. ",
    "Poor {p} has been queueing all morning. ",
    "{P} is just back from fell running, so ",
    "{P}'s been stuck in meetings all day. ",
    "{P} has been orienteering since dawn and is worn out, so ",
    "What with the barn dance last night, {p} is shattered, so ",
    "{P} has been up a ladder since breakfast. ",
    "Having sung with the shanty choir all afternoon, {p} is parched, so ",
    "{P} has been marking essays for hours. ",
)
CONDITIONS = (  # the handover of {o} to {p}: a condition on others' claims is the speaker's hedge
    "If nobody's bagsied the {o}, {p} can have it.",
    "If the {o} is still going spare, {p} would like it.",
    "Provided nobody has spoken for the {o}, it can go to {p}.",
    "Unless someone's already nabbed the {o}, give it to {p}.",
    "So long as no one else has dibs on the {o}, hand it to {p}.",
    "Should the {o} still be up for grabs, {p} will take it.",
)
CONDITIONS_OUTSIDE = (  # refused: the handover hangs on an outside event or a later word
    "If it stops raining, give {p} the {o}.",
    "Give {p} the {o} if the supervisor says so.",
    "If {p} asks for the {o} later, hand it over.",
    "Should the doctor agree, the {o} can go to {p}.",
    "Once the meeting finishes, and only then, {p} gets the {o}.",
)
HYPERBOLES = (  # the handover of {o} to {p}
    "{P} would walk over hot coals for the {o}.",
    "The {o} would be just the ticket for {p}.",
    "The {o} would hit the spot for {p}.",
    "Nothing would please {p} more than the {o}.",
    "{P}'s heart is set on the {o}.",
    "The {o} is top of {p}'s wish list.",
    "{P} would be over the moon with the {o}.",
    "{P} would be chuffed to bits with the {o}.",
    "The {o} would be a godsend for {p}.",
    "{P} would bite your hand off for the {o}.",
    "{P} would queue all night for the {o}.",
    "{P} would swap just about anything for the {o}.",
)
HYPERBOLES_AGAINST = (  # refused: the want said against
    "{P} wouldn't be seen dead with the {o}.",
    "{P} wouldn't touch the {o} with a bargepole.",
    "{P} would sooner starve than have the {o}.",
    "Wild horses couldn't make {p} take the {o}.",
    "{P} would rather go without than have the {o}.",
)
APIECE = (  # {ps} two or three people, {c} a kind ({a} "a" or "an")
    "{Ps} get {a} {c} apiece.",
    "{a} {c} apiece for {ps}.",
    "{Ps} are to have one {c} each.",
    "One {c} each for {ps}, please.",
    "Give {ps} one {c} apiece.",
    "{Ps} should get {a} {c} each.",
)
ONE_FOR = (  # {cs} the kind's plural, {each} "one for Alice and one for Bob"
    "The {cs}: {each}.",
    "Share out the {cs}, {each}.",
    "The {cs} go {each}.",
    "Split the {cs} between them, {each}.",
)
RESPECTIVELY = (  # {x} to {p}, {y} to {q}
    "Give {p} and {q} the {x} and the {y} respectively.",
    "The {x} and the {y} go to {p} and {q} respectively.",
    "{P} and {q} get the {x} and the {y}, respectively.",
    "Hand the {x} and the {y} to {p} and {q}, respectively.",
)
RESPECTIVELY_THREE = (  # refused: three objects for two people
    "Give {p} and {q} the {x}, the {y} and the {z} respectively.",
    "The {x}, the {y} and the {z} go to {p} and {q} respectively.",
)
OWNER_BACK = (  # the handover of {o} to its owner {p} ({them}: "him" / "her" / the name)
    "Take {p}'s {o} back to {them}.",
    "{P}'s {o} needs to go back to {them}.",
    "The {o} {p} had earlier goes back to {them}.",
    "Return the {o} {p} left behind to {them}.",
    "Give {p} back the {o} {p} lent you.",
    "The {o} belongs to {p}; give it back to {them}.",
)
OWNER_OTHER = (  # {q}'s object to {p}: the handover to {p}
    "Take {q}'s {o} over to {p}.",
    "{P} can borrow {q}'s {o}.",
    "Pass {p} the {o} {q} was using.",
    "Give {q}'s {o} to {p} for now.",
)
OWNER_EITHER = (  # refused, {p} and {q} as readings: whose it is is not known
    "The {o} is {p}'s or {q}'s, I forget which; take it back to its owner.",
    "Give the {o} back to whichever of {p} and {q} had it.",
    "Take the {o} back to its owner, {p} or {q}, I'm not sure which.",
    "Either {p} or {q} left the {o} here; return it to them.",
)
HOLDS_BEFORE = (  # a remark before an entry: {q} (a person of the scene) already holds {o}
    "{q}'s got the {o} already, so ",
    "{q} already has the {o}, so ",
    "{q} is already holding the {o}. ",
    "{q} has had the {o} already. ",
    "{q} still has the {o} from earlier, so ",
    "Since {q} has the {o} already, ",
    "{q} has been given the {o} already. ",
)
HOLDS_AFTER = (  # the same after an entry
    ", {q}'s got the {o} already.",
    ". {q} already has the {o}.",
    ". {q} is holding the {o} already.",
    ", as {q} already has the {o}.",
    ". {q} still has the {o} from earlier.",
    ". {q} has been given the {o} already.",
    ", since {q}'s already got the {o}.",
)
HOLDS_OWN = (  # {pos}: "his" / "her" where the name says which, else "their"; before or after
    "{q}'s got {pos} own {o}, so ",
    "{q} has {pos} own {o} already. ",
    "; {q}'s got {pos} own {o}.",
    ". {q} has {pos} own {o} already.",
)
HOLDS_FORMS = ("before", "after", "own", "lower")
RUN_ON = (  # {e} the entry texted; {he} / {hes} "he" / "hes" or "she" / "shes" of its one person
    "{e} {he} asked for it",
    "{e} {hes} been after it all morning",
    "{e} {he} needs it",
    "{e} {hes} waiting on it",
)
TEXTED_FORMS = ("stops", "apostrophes", "texting", "run on")
# antecedents (session 46; blind44's pronoun requests after a sentence naming the person: "That
# apple was set aside for Person A at the swan upping; run it over to her.", "Person B's parched
# after cloud spotting all afternoon, he needs the cup.", "Since the timpani rehearsal Person B
# keeps on about the cup; let him have it, for peace."): a person said by a name in a remark,
# a state or a want, then the handover asked for with a pronoun for them ({he} / {him} "he" /
# "him" or "she" / "her"; {it} / {is} / {was} / {That} "it" / "is" / "was" / "That" or, for an
# object said as a plural, "them" / "are" / "were" / "Those"): that handover
ANTECEDENTS = (
    "{P}'s parched after the fell race, {he} needs the {o}.",
    "{P} is starving after the barn dance, the {o} would do {him} nicely.",
    "{P} keeps on about the {o}; let {him} have {it}, for peace.",
    "{That} {o} {was} set aside for {p}; run {it} over to {him}.",
    "{P} was after the {o}. Bring {it} to {him}, please.",
    "The {o} {is} {p}'s. Hand {it} across to {him}, thanks.",
    "{P} has been asking for the {o} all day, so take {it} to {him}.",
    "{P}'s back from the allotment and {he}'d love the {o}.",
    "{P} mentioned the {o} earlier; pass {it} to {him} when you can.",
)
# two people of one sex said before the pronoun ({p} and {q}): refused, both as readings
ANTECEDENTS_TWO = (
    "{P} and {q} are both parched; {he} needs the {o}.",
    "{P} was telling {q} about the {o}; take {it} to {him}.",
    "{P} and {q} have been at it all day, so the {o} for {him}.",
    "{P} asked {q} for the {o}. Give {it} to {him}, please.",
)
# someone not in the scene of the person's sex said before the pronoun (in ANTECEDENTS for {p}):
# refused, the pronoun is theirs
ABSENT_HE = ("my brother", "the postman", "my uncle")
ABSENT_SHE = ("my sister", "the postwoman", "my aunt")
ANTECEDENT_FORMS = ("named before", "two before", "absent before", "lower")
# thoughts (session 47; blind45's one wrong reading, "Marco's shouting for salt, I thought, but it
# was lemon he wanted, so give Marco the lemon.", and its corrections said as what the speaker
# heard or thought: "Omar asked for the white cup, well, I heard white, but he corrected me: it's
# the green cup he's after."): an entry's one handover of a one-of-a-kind object ({o}) to a person
# ({p}; {P} capitalised) said as a thought, then taken back after 'but' for another one-of-a-kind
# object ({x}): that object to that person
THOUGHT_BACK = (
    "{P} wants the {o}, I thought, but it was the {x} {P} wanted.",
    "Give {p} the {o}, I thought, but it was the {x} {P} asked for.",
    "{P} asked for the {o}, or so I thought, but it's the {x} {P}'s after.",
    "I heard {o} for {p}, but {P} put me right: it's the {x} {P} wants.",
    "{P} was after the {o}, I'd assumed, but no, it's the {x}.",
    "Take {p} the {o}, I reckoned, but actually it was the {x} {P} meant.",
)
# ... taken back for another person of the scene ({q}): the object to them
THOUGHT_PERSON = (  # {it} "it" or "them"
    "Give {p} the {o}, I thought, but it was {q} who asked for {it}.",
    "{P} wants the {o}, or so I thought, but it turns out it's {q} who's after {it}.",
    "The {o} for {p}, I assumed, but it was {q} who wanted {it}.",
)
# ... not taken back but added to ('too', 'as well'): both objects to that person
THOUGHT_ADDED = (
    "{P} wants the {o}, I think, but it's the {x} {P} wants too.",
    "Give {p} the {o}, I think, but {P}'s after the {x} as well.",
    "{P} asked for the {o}, I thought, but it was the {x} {P} wanted too.",
)
# ... or put after another ('first', 'before that'): the other object, then the entry's
THOUGHT_FIRST = (
    "Give {p} the {o}, I think, but it's the {x} {P} needs first.",
    "{P} wants the {o}, I reckon, but the {x} before that.",
)
# after the entry: a hedge with where its object is ({s} a surface; {its} "it's" or "they're"): the
# entry, or refused (where a thing is asks for nothing)
THOUGHT_WHERE = (
    ", I think, but {its} on the {s}.",
    ", I think, but {its} over by the {s}.",
    ", I believe, but {its} on the {s} at the moment.",
    ", I thought, but {its} on the {s} now.",
)
# after the entry: a hedge alone (the entry, or refused)
THOUGHT_HEDGES = (", I think.", ", or so I'm told.", ", I believe.", ", if I heard right.")
THOUGHT_FORMS = ("taken back", "person", "added", "first", "where", "hedge")
# chains (session 48; tuning's "Hand the apple to Bob, no, to Carol, well, the crisps actually."
# read apple>C & chips>C, and "Crisps over to Bob, or, hmm, Alice, so Alice." a choice of three,
# from blind45's "…, or, hmm, Alice called dibs on them first, so Alice."): after an entry's one
# handover of a one-of-a-kind object ({o}) to a person named ({p}), a first correction and a second
# after it. The person ({q}, another of the scene) then the object ({x}, another one-of-a-kind
# object): {x} to {q}
CHAIN_PERSON_OBJECT = (
    ", no, {q}, well, the {x} actually.",
    ". No, {q}. Actually, the {x}.",
    ", sorry, {q}, and I meant the {x}, not the {o}.",
    ", I mean {q}, and make that the {x}.",
)
# ... the object then the person: {x} to {q}
CHAIN_OBJECT_PERSON = (
    ", no, the {x}, well, {q} actually.",
    ". Sorry, the {x}. And it's for {q}, not {p}.",
    ", I mean the {x}, and to {q} rather than {p}.",
    ". Make that the {x}. Oh, and {q}, not {p}.",
)
# ... the object twice ({y} a third one-of-a-kind object): {y} to {p}
CHAIN_OBJECTS = (
    ", no, the {x}, no, the {y}.",
    ". Sorry, the {x}. No wait, the {y}.",
    ", I mean the {x}, or rather the {y}.",
    ", no, the {x}, well, the {y} actually.",
)
# ... the person twice ({r} a third person): {o} to {r}
CHAIN_PEOPLE = (
    ", no, {q}, sorry, {r}.",
    ". Make that {q}. No, {r}, I mean.",
    ", I mean {q}, or rather {r}.",
    ", no, {q}, well, {r} actually.",
)
# ... corrected and put back: the entry
CHAIN_BACK = (
    ", no, the {x}, no, sorry, I had it right the first time: the {o}.",
    ". Or the {x}? No, the {o}, I had it right.",
    ", no, {q}, hang on, I had it right the first time: {p}.",
    ". Or {q}? No, {p}, I had it right.",
)
# ... a hesitation between people and what it settles on (the key of the person): {o} to them
CHAIN_HESITATIONS = (
    (", or, hmm, {q}, so {q}.", "q"),
    (", or, um, {q}? No, {p}, stick with {p}.", "p"),
    (", or maybe {q}, yes, {q}.", "q"),
    (", or, hmm, {q}, or {r}, so {r}.", "r"),
)
# ... a second object added, then the person and an object of the two corrected: refused (which
# does {y} replace? {o} and {x} as readings)
CHAIN_WHICH = (
    ", and the {x}, no, {q}, well, the {y} actually.",
    ". And the {x}. No, {q}, well, the {y} actually.",
)
# ... the person corrected, then a placing instead ({s} a surface): {o} on {s}
CHAIN_PLACED = (
    ", no, {q}, well, put it on the {s} instead.",
    ", no, {q}, actually, just pop it on the {s} instead.",
)
# After an entry's one placing of a one-of-a-kind object ({o}) on a surface ({s}) naming no person:
# the surface corrected ({t} another) then a handover instead: {o} to {q}
CHAIN_SURFACE_PERSON = (
    ", no, the {t}, well, give it to {q} instead.",
    ". Sorry, the {t}. Actually, just hand it to {q} instead.",
)
# ... the surface corrected and put back: the entry
CHAIN_SURFACE_BACK = (
    ", no, the {t}, sorry, I had it right the first time: the {s}.",
    ". Or the {t}? No, the {s}, I had it right.",
)
# ... the surface then the object: {x} on {t}
CHAIN_SURFACE_OBJECT = (
    ", no, the {t}, and the {x}, not the {o}.",
    ". The {t}, sorry. And it's the {x}, not the {o}.",
)
CHAIN_FORMS = (
    "person, object",
    "object, person",
    "objects",
    "people",
    "back",
    "hesitation",
    "which",
    "placed",
    "surface, person",
    "surface back",
    "surface, object",
)
# forgets (session 49; blind47's wrong reading "Kofi wanted one of the spanners for the
# stonecarver's job, the small or the large, it's gone clean out of my head." read as the robot's
# choice; the lead's rule knows a list of such remarks, and 12c's probes found others read so):
# a remark closing a choice that says the speaker has forgotten or never knew which was asked for
# (no 'which' in it: the older families say "…, I forget which"); the choice is the person's, lost
# by the speaker, not one left to the robot: refused
FORGET_CLOSERS = (
    ", it's gone clean out of my head.",
    ", I've clean forgotten.",
    ", my mind's gone blank.",
    ", it's slipped my mind.",
    ", it went right out of my head.",
    ", I didn't catch it.",
    ", I wasn't listening.",
    ", I never wrote it down.",
    ", it's gone clean out of my head, sorry.",
    ", memory's shot.",
    ", can't remember now.",
    ", dunno.",
    # session 50: the five meanings of the lead's `forgets50l` (forgetting, going blank, losing
    # track, memory denied, doubt) and the wordings 12c's probes found it missing
    ", I've gone blank on which.",
    ", I've lost track.",
    ", can't recall which.",
    ", haven't a clue.",
    ", I'm drawing a blank.",
    ", my memory's failed me.",
    ", it's on the tip of my tongue.",
    ", I'm a bit hazy on which.",
    ", I wasn't paying attention.",
    ", I couldn't tell you.",
    ", your guess is as good as mine.",
    ", I've lost it.",
    ", I'm not quite sure.",
    ", I'd have to check.",
    ", it didn't stick.",
    ", I only half heard.",
    # session 56 (12c): only that it was one of the two, in the past (blind54 #99: "…, the torch
    # or the hammer, it was one of those." read as a free choice; wordings the lead's fix missed)
    ", it was one of those.",
    ", it was one of those ones.",
    ", it was either one or the other.",
)
# ... and a remark after a choice that is no forgetting (the speaker does not mind, or is sure
# either will do): the choice stands (`free`: the entry; session 50's rule must not take these)
FORGET_FREE = (
    ", I don't mind which.",
    ", either's fine, I'm sure.",
    ", I'm not fussy which.",
    ", I'm sure either will do.",
    ", whichever, I really don't mind.",
)
# ... said of the entry's one handover of a one-of-a-kind object ({o}) to a person named ({p}):
# that object or another ({x}), closed by a remark ({c}): refused, both as readings
FORGET_OBJECTS = (
    "{P} wanted the {o} or the {x}{c}",
    "{P} asked for the {o} or the {x}{c}",
    "It was the {o} or the {x} {p} was after{c}",
    "{P} needs the {o}, or was it the {x}{c}",
)
# ... that object or another asked for, then which it was said (session 56, 12c: read on main as
# the robot's choice): the entry's handover
FORGET_NAMED = (
    "{P} asked for the {x} or the {o}, it was the {o}.",
    "{P} wanted the {o} or the {x}; it was the {o}.",
    "{P} asked for one of them, the {x} or the {o}, it was the {o}.",
    "{P} was after the {x} or the {o}, it was the {o} {p} wanted.",
)
# ... that person or another ({q}): refused
FORGET_PEOPLE = (
    "It was {p} or {q} who wanted the {o}{c}",
    "{P} or {q} wanted the {o}{c}",
)
# (not after a choice said to be free, "either plate, she's not bothered": a remark of forgetting
# after it says nothing a careful person could read)
_FREE_CHOICE = frozenset(
    (
        "either",
        "any",
        "whichever",
        "whatever",
        "choice",
        "bothered",
        "fussy",
        "mind",
        "matter",
        # session 51: the free choices session 50's `closed` took for forgetting ("…, I'm easy",
        # "I don't care which", "I'll let you pick", "Your call which")
        "easy",
        "care",
        "pick",
        "call",
        # session 52: "I'm not fussed which" (session 51's one false wrong reading of `closed`)
        "fussed",
    )
)
FORGET_FORMS = ("closed", "objects", "people", "free", "named")
# kin (session 50; 12r's "Grandad said she wants the teddy." read teddy>B, session 34's check of
# a pronoun against the people named knowing first names only): a he / she who wants, or a him /
# her who is given, said of a person the scene names by a word of kin or a title of the other sex
# ({K}) cannot be that person (the lead's session-50 decision): refused; the entry's one-of-a-kind
# object ({o}), the pronoun as subject ({s}) or object ({h})
KIN_NAMED = frozenset(("Grandad", "Mr Lee", "Mr Novak", "Mrs Ortiz", "Mrs Khan"))
KIN_WANTS = (
    "{K} says {s} wants the {o}.",
    "{K} said {s}'d like the {o}.",
    "{K} reckons {s}'s after the {o}.",
    "{K} says {s}'s been asking for the {o}.",
    "{K} says {s}'s desperate for the {o}.",
    "{K} mentioned {s} could do with the {o}.",
)
KIN_GIVEN = (
    "{K} asked for the {o}, give it to {h}.",
    "{K}'s asked for the {o}, let {h} have it.",
    "{K}'s asked for the {o}, it's for {h}.",
    "{K} wants the {o}, {s} can have it.",
    "{K}'s asked for the {o}, hand it over to {h}.",
)
# ... the pronoun of that person's own sex, where no one else of the scene is of it: that person
# (`same`, KIN_WANTS: read as before)
KIN_FORMS = ("wants", "given", "same")
# lots (session 49; blind47's wrong reading "Load the belt with the three boxes, the whole lot,
# the brickie's van is nearly here." read every object of the depot onto the belt): 'the whole
# lot' in apposition after a kind's plural that names every one of the kind ({cs}) says the kind
# again (the lead's decision: the kind), for a person ({p}) or on a surface ({s})
LOT_KIND = (
    "Give {p} the {cs}, the whole lot.",
    "Give {p} the {cs}, the lot.",
    "The {cs} for {p}, the whole lot of them.",
    "Give {p} the {cs} - the whole lot.",
    "Give {p} the lot, the {cs}.",
    "Hand {p} the {cs}, the whole lot, cheers.",
)
LOT_PLACED = (
    "Put the {cs} on the {s}, the whole lot.",
    "The {cs}, the lot, on the {s} please.",
    "Put the {cs} on the {s} - the whole lot.",
    "Load the {s} with the {cs}, the whole lot, we're nearly done.",
)
# ... after other named things that are not everything in the scene (the entry's one-of-a-kind
# object {o} and another, {x}, for the entry's person): those again or everything else: refused,
# both named as readings
LOT_NAMED = (
    "Give {p} the {o} and the {x}, the whole lot.",
    "Give {p} the {o}, the {x}, the lot.",
    "The {o} and the {x} for {p}, the whole lot.",
)
LOT_FORMS = ("kind", "placed", "named")
# done (session 51; 12c's probes: a handover said as already done, or as no request at all, was
# read as a request in words the older refusals miss): for an entry's one handover of a
# one-of-a-kind object ({o}) to a person named ({p}, {P} at a sentence's start; {q} / {Q} another
# person named): refused
DONE_SAID = (
    "Gave {p} the {o}.",
    "The {o} went to {p}.",
    "The {o}'s gone over to {p}.",
    "{P} has received the {o}.",
    "You brought {p} the {o}.",
    "Great job getting the {o} to {p}.",
    "{P}, our new starter, had the {o}.",
    "{Q} says {p} has the {o}.",
    "{P} or {q} had the {o}.",
)
# ... the entry, then a remark that it is seen to: refused
DONE_AFTER = (
    ", it's all sorted.",
    ", I've done it already.",
    ", I'll see to it myself.",
    ". Oh, that's been done.",
    # session 55 (12c): the handover itself said as made (read on main after a request or a want)
    ", I've already handed that over.",
    ", that's been handed over already.",
    ". I gave that over earlier.",
    # session 56 (12c): with a time of the handover, or 'that one' (read on main 085b81dc)
    ", I handed it over this morning.",
    ", I already handed that one over.",
)
# ... ticked off, then another one-of-a-kind object ({x}) for the person: that handover only
DONE_CHECKLIST = (
    "The {o} to {p}: done. The {x} to {p}, please.",
    "{O} to {p} - done. Now the {x} to {p}.",
)
# ... a want of it replaced by a want of {x}: that handover only
DONE_REPLACED = (
    "{P} wanted the {o}, now {p} wants the {x}.",
    "{P} asked for the {o} earlier, but now {p}'s after the {x}.",
)
DONE_FORMS = ("said", "after", "checklist", "replaced")
SAID_FORMS = (
    "reason before",
    "condition",
    "condition outside",
    "hyperbole",
    "hyperbole against",
    "apiece",
    "apiece short",
    "one for",
    "respectively",
    "respectively short",
    "owner",
    "owner other",
    "owner either",
    "lower",
    "typo",
)
Family = Literal[
    "wrappers",
    "takebacks",
    "references",
    "exclusions",
    "tails",
    "asides",
    "afterthoughts",
    "frames",
    "repairs",
    "deferrals",
    "clefts",
    "counts",
    "remarks",
    "purposes",
    "idioms",
    "turns",
    "said",
    "holds",
    "texted",
    "antecedents",
    "thoughts",
    "chains",
    "forgets",
    "lots",
    "kin",
    "done",
]
FAMILIES: tuple[Family, ...] = get_args(Family)

Must = Literal["same", "refuse"]


@dataclass(frozen=True, slots=True)
class Variant:
    part: str
    scene: str
    text: str
    want: Node | None  # what it must read as (None: refused); a refusal is always allowed
    must: Must
    family: Family = "wrappers"
    readings: tuple[str, ...] = ()  # ids a refusal must name (else it is "unclear")
    form: str = ""  # which of its family's kinds (references: REFERENCE_FORMS)
    added: Task | None = None  # tails: the handover the tail adds (see ``kept``)


def _name(scene: Scene, oid: str) -> str:
    for o in scene.objects:
        if o.id == oid:
            return o.aliases[0] if o.aliases else o.id
    h = next(h for h in scene.humans if h.id == oid)
    shared = {a for x in scene.humans if x.id != oid for a in x.aliases}
    return next((a for a in (*h.aliases, h.name) if a not in shared), h.name)


def _unique_objects(scene: Scene) -> list[str]:
    cats = [o.category for o in scene.objects]
    return [o.id for o in scene.objects if cats.count(o.category) == 1]


def _named(text: str, scene: Scene, kind: Literal["object", "human", "surface"]) -> set[str]:
    try:
        items = lex(text, Lexicon.of(scene))
    except GroundingError:
        return set()
    return {r.id for it in items if it.kind == "ent" for r in it.refs if r.kind == kind}


def _objects_named(text: str, scene: Scene) -> set[str]:
    return _named(text, scene, "object")


def variants(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The fuzz's variants of one entry (three openers, three closers, one of each together,
    three near openers, two near closers; corrections for an entry of one handover)."""
    text = entry.text.strip()
    bare = text.rstrip(".!")
    plain_end = not text.endswith("?")
    objects = _unique_objects(scene)
    # a near form names an object the entry does not (one it names may be only said again)
    named = {t.obj for t in tasks(entry.want)} if entry.want is not None else set()
    unnamed = [x for x in objects if x not in named] or objects
    oid = rng.choice(unnamed) if unnamed else ""
    o = _name(scene, oid) if oid else "thing"
    p = _name(scene, rng.choice(scene.humans).id)
    # (session 30) the speaker's want of an object the entry's words name restates or corrects
    # the entry ("We need the knife, not the knife, the tongs, for Marco" is the tongs for Marco,
    # as a careful person reads it; the references family's speaker forms skip it since session
    # 29): such a near opener is not made (the draws stay as they were, so a seed's other
    # variants do too)
    restated = bool(oid) and oid in _objects_named(text, scene)

    def said(opener: str, body: str) -> str:
        if opener.endswith(("but ", "so ", ", ")) and body[:1].isupper() and body[1:2].islower():
            body = body[:1].lower() + body[1:]
        return opener + body

    for opener in rng.sample(OPENERS, 3):
        yield Variant(part, entry.scene, said(opener, text), entry.want, "same")
    if plain_end:
        for closer in rng.sample(CLOSERS, 3):
            yield Variant(part, entry.scene, bare + closer, entry.want, "same")
        both = said(rng.choice(OPENERS), bare) + rng.choice(CLOSERS)
        yield Variant(part, entry.scene, both, entry.want, "same")
    # (not before an entry that opens by taking back what came before: "Scratch that - …")
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    for near in rng.sample(NEAR_OPENERS, 3):
        if not takes_back and not (restated and "{o}" in near):
            yield Variant(part, entry.scene, said(near.format(o=o, p=p), text), None, "refuse")
    if plain_end:
        for near in rng.sample(NEAR_CLOSERS, 2):
            yield Variant(part, entry.scene, bare + near.format(o=o, p=p), None, "refuse")
    want = entry.want
    # a correction to another object (only where the entry names no other object, which the
    # correction could replace instead: "… Do not give him the gloves, no, the scanner")
    if (
        plain_end
        and isinstance(want, Task)
        and want.kind == "deliver"
        and _objects_named(text, scene) <= {want.obj}
    ):
        others = [x for x in objects if x != want.obj]
        if others:
            other = rng.choice(others)
            fixed = Task("deliver", other, want.target)
            form = rng.choice(CORRECTIONS)
            yield Variant(
                part, entry.scene, bare + form.format(o=_name(scene, other)), fixed, "same"
            )
        cut = rng.choice(CUT_OFF)
        yield Variant(part, entry.scene, bare + cut.format(p=p), None, "refuse")


def _capitalised(scene: Scene) -> set[str]:
    """Words that keep their capital after an opener: people's names and titles."""
    words = {"Mr", "Mrs", "Ms", "Miss", "Dr", "Person", "Robot"}
    for h in scene.humans:
        for name in (h.name, *h.aliases):
            words.update(w for w in name.split() if w[:1].isupper())
    return words


def _after(opener: str, body: str, scene: Scene) -> str:
    """``body`` after ``opener``: a first word in capitals only for the sentence (not a name or
    title of the scene) in lower case after a comma."""
    first = body.split(" ", 1)[0].strip(",.!?:;")
    if (
        opener.endswith((", ", "but ", "so ", "and "))
        and body[:1].isupper()
        and body[1:2].islower()
        and first not in _capitalised(scene)
    ):
        body = body[:1].lower() + body[1:]
    return opener + body


def takebacks(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The take-back variants of one entry: one taken back (refused); for a grounded entry of one
    task naming one object, one taken back and replaced by a handover of another object (that
    handover); for a grounded entry with no choice in it, one opener letting go of an object it
    does not name (the entry)."""
    text = entry.text.strip()
    bare = text.rstrip(".!")
    plain_end = not text.endswith("?")
    objects = _unique_objects(scene)
    p = _name(scene, rng.choice(scene.humans).id)
    forms = [f for f in TAKEN_BACK if plain_end or f.startswith(". ")]
    back = rng.choice(forms).format(p=p)
    said = bare + back if plain_end else text + back[1:]
    yield Variant(part, entry.scene, said, None, "refuse", "takebacks")
    want = entry.want
    if want is None:
        return
    named = _objects_named(text, scene) | {t.obj for t in tasks(want)}
    if isinstance(want, Task) and _objects_named(text, scene) <= {want.obj}:
        others = [x for x in objects if x != want.obj]
        if others:
            other = rng.choice(others)
            target = rng.choice(scene.humans).id
            forms = [f for f in REPLACED if plain_end or f.startswith(". ")]
            form = rng.choice(forms).format(o=_name(scene, other), p=_name(scene, target))
            said = bare + form if plain_end else text + form[1:]
            fixed = Task("deliver", other, target)
            yield Variant(part, entry.scene, said, fixed, "same", "takebacks")
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    unnamed = [x for x in objects if x not in named]
    if unnamed and not takes_back and not has_choice(want):
        opener = rng.choice(LET_GO).format(o=_name(scene, rng.choice(unnamed)))
        yield Variant(part, entry.scene, _after(opener, text, scene), want, "same", "takebacks")


def _words(text: str) -> set[str]:
    return set(re.findall(r"[a-z]+", text.lower()))


def _shared(scene: Scene) -> tuple[dict[str, tuple[str, ...]], dict[str, tuple[str, ...]]]:
    """The kinds the scene has several objects of and the titles several of its people share,
    each with their ids, where the lexer reads "the <kind>" / "the <title>" as every one."""
    kinds: dict[str, list[str]] = {}
    for o in scene.objects:
        kinds.setdefault(o.category, []).append(o.id)
    titles: dict[str, list[str]] = {}
    for h in scene.humans:
        for a in h.aliases:
            titles.setdefault(a, []).append(h.id)
    return (
        {
            c: tuple(ids)
            for c, ids in kinds.items()
            if len(ids) > 1 and _named(f"the {c}", scene, "object") == set(ids)
        },
        {
            t: tuple(ids)
            for t, ids in titles.items()
            if len(ids) > 1 and _named(f"the {t}", scene, "human") == set(ids)
        },
    )


# words that may tell one object or person of a kind from another ("the one on the left")
_TELLING = frozenset(
    [
        "other",
        "another",
        "else",
        "rest",
        "left",
        "right",
        "first",
        "second",
        "third",
        "last",
        "near",
        "nearest",
        "closest",
        "far",
        "furthest",
        "end",
        "middle",
    ]
)


def _telling(scene: Scene, ids: tuple[str, ...], kind: str) -> set[str]:
    """Words that tell the objects ``ids`` of ``kind`` apart, or point at a place."""
    words = set(_TELLING)
    for o in scene.objects:
        if o.id in ids:
            words |= _words(" ".join((o.id.replace("_", " "), *o.aliases)))
    for s in scene.surfaces:
        words |= _words(" ".join((s.id, *s.aliases)))
    return words - _words(kind)


def _said_by_kind(
    text: str, scene: Scene, oid: str, kind: str, ids: tuple[str, ...], rng: random.Random
) -> str | None:
    """``text`` with its one naming of ``oid`` by a name that tells it apart ("the blue
    blanket") said by its kind alone ("the blanket", "the one blanket", "that blanket"; "her
    blanket"), or None where nothing else in it may tell which is meant."""
    obj = next(o for o in scene.objects if o.id == oid)
    names = sorted((a for a in obj.aliases if a.lower().endswith(" " + kind)), key=len)
    for name in reversed(names):
        m = re.search(rf"(?i)\b(the|that|this|her|his|their)( {re.escape(name)})\b", text)
        if m is None:
            continue
        rest = text[: m.start()] + text[m.end() :]
        if _named(rest, scene, "object") & set(ids) or _words(rest) & _telling(scene, ids, kind):
            return None
        if m[1].lower() in ("the", "that", "this"):
            said = rng.choice(THE_KIND).format(c=kind)
            said = said[:1].upper() + said[1:] if m[1][:1].isupper() else said
        else:
            said = f"{m[1]} {kind}"
        return text[: m.start()] + said + text[m.end() :]
    return None


def _said_by_title(
    text: str, scene: Scene, hid: str, title: str, ids: tuple[str, ...]
) -> str | None:
    """``text`` with its one naming of ``hid`` by a name ("Mrs Khan") said by a title another
    shares ("the patient"), or None where anything else in it may tell which is meant."""
    h = next(h for h in scene.humans if h.id == hid)
    shared = {a for x in scene.humans if x.id != hid for a in x.aliases}
    names = sorted((n for n in (h.name, *h.aliases) if n not in shared), key=len)
    for name in reversed(names):
        m = re.search(rf"(?<![\w'])(the |The )?{re.escape(name)}\b", text)
        if m is None or m[1]:
            continue
        rest = text[: m.start()] + text[m.end() :]
        if _named(rest, scene, "human") & set(ids) or _words(rest) & (_GENDERED | _TELLING):
            return None
        first = not text[: m.start()].strip() or text[: m.start()].rstrip()[-1] in ".!?"
        said = ("The " if first else "the ") + title
        return text[: m.start()] + said + text[m.end() :]
    return None


def references(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The reference variants of one entry: for a grounded entry with no choice in it naming
    its one object of a kind the scene has several of by a name that tells it apart, that
    object said by its kind alone (refused with every one of the kind as readings), and its one
    person of a shared title said by the title (refused with the people who share it); a short
    request, want or correction naming such a kind alone (refused with the readings) and one
    naming a one-of-a-kind object by its kind (that handover); the speaker's own want joined to
    the entry (refused; every opener before an entry that opens "For/To <person>, …")."""
    text = entry.text.strip()
    want = entry.want
    kinds, titles = _shared(scene)
    people = [(h.id, _name(scene, h.id)) for h in scene.humans]
    if want is not None and not has_choice(want):
        objs = {t.obj for t in tasks(want)}
        named = _named(text, scene, "object")
        for kind, ids in kinds.items():
            hits = objs & set(ids)
            if len(hits) != 1 or named & set(ids) != hits:
                continue
            (oid,) = hits
            said = _said_by_kind(text, scene, oid, kind, ids, rng)
            if said is not None:
                yield Variant(
                    part, entry.scene, said, None, "refuse", "references", ids, "kind alone"
                )
        whom = {t.target for t in tasks(want) if t.target is not None}
        met = _named(text, scene, "human")
        for title, ids in titles.items():
            hits = whom & set(ids)
            if len(hits) != 1 or met & set(ids) != hits:
                continue
            said = _said_by_title(text, scene, next(iter(hits)), title, ids)
            if said is not None:
                yield Variant(part, entry.scene, said, None, "refuse", "references", ids, "title")
    hid, p = rng.choice(people)
    unique = _unique_objects(scene)
    if kinds and unique:
        kind, ids = rng.choice(sorted(kinds.items()))
        form = rng.choice(KIND_FRAMES)
        said = form.format(P=p[:1].upper() + p[1:], p=p, c=kind, u=_name(scene, rng.choice(unique)))
        how = rng.randrange(3)
        if how == 1:
            said = _after(rng.choice(OPENERS), said, scene)
        elif how == 2 and said.endswith("."):
            said = said[:-1] + rng.choice(CLOSERS)
        yield Variant(part, entry.scene, said, None, "refuse", "references", ids, "frame")
    alone = [  # (a kind said in the plural, "the one chips", is left out)
        (u, o.category)
        for u in unique
        for o in scene.objects
        if o.id == u
        and not o.category.endswith("s")
        and _named(f"the {o.category}", scene, "object") == {u}
    ]
    if len(alone) > 1:
        (u, kind), (other, _) = rng.sample(alone, 2)
        form = rng.choice(KIND_FRAMES)
        said = form.format(P=p[:1].upper() + p[1:], p=p, c=kind, u=_name(scene, other))
        fixed = Task("deliver", u, hid)
        yield Variant(part, entry.scene, said, fixed, "same", "references", (), "one of a kind")
    # the speaker's own want
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    named = _named(text, scene, "object") | (
        {t.obj for t in tasks(want)} if want is not None else set()
    )
    # (session 29) only an object the entry does not name: the speaker's want of the entry's own
    # object restates the entry ("We need the bottle, not the chips this time, the bottle, over to
    # Person B at the map table." is the bottle to Person B, as a careful person reads it); the
    # object is still drawn where there is none, so a seed's later variants stay as they were
    fresh = [x for x in unique if x not in named]
    unnamed = fresh or unique
    if not unnamed or takes_back:
        return
    o = _name(scene, rng.choice(unnamed))
    if text.lower().startswith(("for ", "to ")):
        for form in SPEAKER_OPENERS if fresh else ():
            said = _after(form.format(o=o), text, scene)
            yield Variant(part, entry.scene, said, None, "refuse", "references", (), "speaker")
        return
    plain_end = not text.endswith("?")
    forms = [*SPEAKER_OPENERS, *(f for f in SPEAKER_CLOSERS if plain_end or f.startswith(". "))]
    form = rng.choice(forms)
    if not fresh:
        return
    if form in SPEAKER_OPENERS:
        said = _after(form.format(o=o), text, scene)
    elif plain_end:
        said = text.rstrip(".!") + form.format(o=o)
    else:
        said = text + form.format(o=o)[1:]
    yield Variant(part, entry.scene, said, None, "refuse", "references", (), "speaker")


def _plural(kind: str) -> str:
    return kind + ("es" if kind.endswith(("s", "x", "ch", "sh")) else "s")


def _told_apart(scene: Scene) -> list[tuple[str, str, tuple[str, ...], dict[str, str]]]:
    """The kinds the scene has several objects of whose plural the lexer reads as every one, each
    with that plural, its ids and, for each object with one, a word that tells it apart ("red" of
    "red mug": "the red mug" read as that one alone)."""
    kinds, _ = _shared(scene)
    out = []
    for kind, ids in kinds.items():
        plural = _plural(kind)
        if _named(f"the {plural}", scene, "object") != set(ids):
            continue
        words: dict[str, str] = {}
        for o in scene.objects:
            if o.id not in ids:
                continue
            for alias in sorted(o.aliases, key=len):
                word, _, rest = alias.partition(" ")
                if rest == kind and _named(f"the {word} {kind}", scene, "object") == {o.id}:
                    words[o.id] = word
                    break
        if words:
            out.append((kind, plural, ids, words))
    return out


def _wrapped(said: str, scene: Scene, rng: random.Random) -> str:
    """``said`` bare, after an opener, before a closer, or (half the time) both."""
    how = rng.choice(("bare", "opener", "closer", "both", "both", "both"))
    if how in ("closer", "both") and said.endswith((".", "!")):
        said = said.rstrip(".!") + rng.choice(CLOSERS)
    if how in ("opener", "both"):
        opener = rng.choice(OPENERS)
        if said.startswith("A ") and opener.endswith((", ", "but ", "so ")):
            said = "a " + said[2:]  # (an article _after leaves alone)
        said = _after(opener, said, scene)
    return said


def exclusions(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The exclusion variants of one entry: for a scene with a kind it has several of, one request
    narrowing that kind after a comma (REST_ANY: a choice of the others; REST_ALL: all the others;
    ONLY_THAT: the one named; JUST_ONE: refused with every one of the kind as readings), bare or
    inside an opener and a closer; and an entry that narrows after a comma inside an opener and a
    closer (as the entry, or refused)."""
    text = entry.text.strip()
    told = _told_apart(scene)
    if told:
        kind, plural, ids, words = rng.choice(told)
        oid = rng.choice(sorted(words))
        hid = rng.choice(scene.humans).id
        p = _name(scene, hid)
        rest = tuple(Task("deliver", i, hid) for i in ids if i != oid)
        form_name = rng.choice(EXCLUSION_FORMS[:4])
        forms: tuple[str, ...]
        want: Node | None
        must: Must = "same"
        readings: tuple[str, ...] = ()
        if form_name == "rest, any":
            forms, want = REST_ANY, rest[0] if len(rest) == 1 else Group("or", rest)
        elif form_name == "rest, all":
            forms, want = REST_ALL, rest[0] if len(rest) == 1 else Group("and", rest)
        elif form_name == "only that":
            forms, want = ONLY_THAT, Task("deliver", oid, hid)
        else:
            forms, want, must, readings = JUST_ONE, None, "refuse", ids
        form = rng.choice([f for f in forms if len(ids) == 2 or not f.startswith("Both")])
        said = form.format(P=p[:1].upper() + p[1:], p=p, c=kind, cs=plural, x=words[oid])
        said = _wrapped(said, scene, rng)
        yield Variant(part, entry.scene, said, want, must, "exclusions", readings, form_name)
    if _NARROWS.search(text):
        if text.endswith("?"):
            said = _after(rng.choice(OPENERS), text, scene)
        else:
            said = _after(rng.choice(OPENERS), text.rstrip(".!"), scene) + rng.choice(CLOSERS)
        must = "same" if entry.want is not None else "refuse"
        yield Variant(
            part, entry.scene, said, entry.want, must, "exclusions", entry.readings, "wrapped"
        )


def _sentence_and_free(entry: Entry, scene: Scene) -> tuple[str, list[str]]:
    """The entry's text as a sentence (a full stop after it where it has none) and the
    one-of-a-kind objects of ``scene`` it does not name (nor move)."""
    text = entry.text.strip()
    if not text.endswith((".", "!", "?")):
        text += "."
    named = _objects_named(text, scene) | (
        {t.obj for t in tasks(entry.want)} if entry.want is not None else set()
    )
    return text, [x for x in _unique_objects(scene) if x not in named]


def tails(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The tail variants of one entry: a sentence after it adding a handover of an object it does
    not name to a person (for an entry that reads: the entry's reading and that handover, see
    ``kept``), and a sentence that must be refused (after any entry)."""
    text, free = _sentence_and_free(entry, scene)
    hid = rng.choice(scene.humans).id
    p = _name(scene, hid)
    if free and entry.want is not None:
        oid = rng.choice(free)
        added = Task("deliver", oid, hid)
        tail = rng.choice(TAIL_ADDS).format(o=_name(scene, oid), p=p, P=p[:1].upper() + p[1:])
        want = Group("and", (entry.want, added))
        yield Variant(part, entry.scene, text + tail, want, "same", "tails", (), "adds", added)
    o = _name(scene, rng.choice(free or _unique_objects(scene) or [scene.objects[0].id]))
    tail = rng.choice(TAIL_REFUSED).format(o=o, p=p)
    yield Variant(part, entry.scene, text + tail, None, "refuse", "tails", (), "refused")


def _names_nothing(words: str, scene: Scene) -> bool:
    """Whether ``words`` name no object, person or surface of ``scene`` (nor one a typo away):
    no word of them nor two together lexed alone as one (the lexer joins an unknown word to a
    name after it: "kettle boils" is one unknown)."""
    said = re.findall(r"[A-Za-z']+", words)
    for n in (1, 2):
        for i in range(len(said) - n + 1):
            try:
                items = lex(" ".join(said[i : i + n]), Lexicon.of(scene))
            except GroundingError:
                return False
            if any(it.kind == "ent" for it in items):
                return False
    return True


def _people_said(text: str, scene: Scene) -> list[re.Match[str]]:
    """Where ``text`` says a person of ``scene`` by a name ("Alice", "Mr Novak", "Person B"; any
    case), not after "the"/"a" nor before a possessive; a name inside a longer one is left out."""
    names = {n for h in scene.humans for n in (h.name, *h.aliases) if n[:1].isupper()}
    found: list[re.Match[str]] = []
    for name in sorted(names, key=len, reverse=True):
        for m in re.finditer(rf"(?i)(?<![\w'])(?<!the )(?<!a ){re.escape(name)}\b(?!['’])", text):
            if not any(f.start() <= m.start() < f.end() for f in found):
                found.append(m)
    return sorted(found, key=lambda m: m.start())


def asides(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The aside variants of one entry: a remark naming nothing of the scene before it and one
    after it, and a trade after one of the people it names ("Alice the baker", "…to Alice, the
    baker."), each read as the entry (or refused; a refused entry must stay refused, with its
    readings)."""
    text = entry.text.strip()
    must: Must = "same" if entry.want is not None else "refuse"

    def aside(said: str, form: str) -> Variant:
        return Variant(part, entry.scene, said, entry.want, must, "asides", entry.readings, form)

    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    before = [a for a in ASIDES_BEFORE if _names_nothing(a, scene)]
    if before and not takes_back:
        yield aside(_after(rng.choice(before), text, scene), "before")
    question = text.endswith("?")
    after = [a for a in ASIDES_AFTER if _names_nothing(a, scene) and not (question and a[0] == ",")]
    if after:
        form = rng.choice(after)
        said = text + form[1:] if question else text.rstrip(".!") + form
        yield aside(said, "after")
    trades = [t for t in TRADES if _names_nothing(f"the {t}", scene)]
    said_at = _people_said(text, scene)
    if trades and said_at:
        m, trade = rng.choice(said_at), rng.choice(trades)
        end = re.match(r"\s*(?:[.!?]|$)", text[m.end() :]) is not None
        put = f", the {trade}" if end and rng.random() < 0.5 else f" the {trade}"
        yield aside(text[: m.end()] + put + text[m.end() :], "trade")


def _then(text: str, form: str) -> str:
    """``form`` (opening "," or ". ") said after ``text``: after a question only a sentence."""
    if text.endswith("?"):
        return text + form[1:]
    return text.rstrip(".!") + form


def _one_person_said(text: str, want: Node | None, scene: Scene) -> tuple[str, Task] | None:
    """For ``text`` grounded as one handover (``want``) naming its one person by a name once and
    no other person or object, and no pronoun for a person: that name as ``text`` says it, and the
    handover; else None."""
    said_at = _people_said(text, scene)
    if (
        isinstance(want, Task)
        and want.kind == "deliver"
        and want.target is not None
        and not _words(text) & _PRONOUNS
        and len(said_at) == 1
        and _named(text, scene, "human") == {want.target}
        and _named(said_at[0][0], scene, "human") == {want.target}
        and _objects_named(text, scene) <= {want.obj}
    ):
        return said_at[0][0], want
    return None


def afterthoughts(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The afterthought variants of one entry. For a grounded entry of one handover naming its
    one person by a name and no other person or object (and no pronoun for a person): that person
    corrected to another after it (RECIPIENT_FIXES, once with a REASONS remark naming nothing:
    that object to that person) and left undecided (UNDECIDED: refused). For a grounded entry
    with no choice and no pronoun for a person: a person's state before or after it (STATES: the
    entry). For a grounded entry with no choice whose handovers move distinct objects: their
    count restated after it (COUNTS: the entry) and miscounted by one (refused)."""
    text = entry.text.strip()
    want = entry.want
    if want is None:
        return
    plain_end = not text.endswith("?")
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    pronoun = bool(_words(text) & _PRONOUNS)

    def variant(said: str, to: Node | None, form: str) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, said, to, must, "afterthoughts", (), form)

    said = _one_person_said(text, want, scene)
    if said is not None and not takes_back:
        p, handover = said
        others = [h.id for h in scene.humans if h.id != handover.target]
        if others:
            q = _name(scene, rng.choice(others))
            to = Task("deliver", handover.obj, _one_id(q, scene))
            forms = [f for f in RECIPIENT_FIXES if plain_end or f.startswith(". ")]
            yield variant(_then(text, rng.choice(forms).format(p=p, q=q)), to, "recipient")
            form, reason = rng.choice(forms).format(p=p, q=q), rng.choice(REASONS)
            fixed = form[:-1] + reason + "." if form.endswith(".") else form + reason
            yield variant(_then(text, fixed), to, "reason")
            forms = [f for f in UNDECIDED if plain_end or f.startswith(". ")]
            yield variant(_then(text, rng.choice(forms).format(p=p, q=q)), None, "undecided")
    if has_choice(want):
        return
    if not pronoun:
        who = _name(scene, rng.choice(scene.humans).id)
        who = who[:1].upper() + who[1:]
        states = [f for f in STATES if _names_nothing(f.replace("{P}", ""), scene)]
        if states:
            state = rng.choice(states).format(P=who)
            before = rng.random() < 0.5 and not takes_back
            said = state + " " + text if before else _then(text, ". " + state)
            yield variant(said, want, "state")
    moved = [t.obj for t in tasks(want)]
    n = len(moved)
    if len(set(moved)) == n and n < len(_NUMBERS):
        form = rng.choice([f for f in COUNTS if plain_end or f.startswith(". ")])
        off = n + 1 if n == 1 or rng.random() < 0.5 else n - 1
        for count, to, name in ((n, want, "count"), (off, None, "miscount")):
            word = _NUMBERS[count - 1]
            things = "thing" if count == 1 else "things"
            said = form.format(n=word, N=word[:1].upper() + word[1:], things=things)
            yield variant(_then(text, said), to, name)


def frames(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The frame variants of one entry. For a grounded entry of one handover of a one-of-a-kind
    object to a person: that handover said in a want frame (WANT_FRAMES: the handover), as a want
    the speaker was told of (TOLD: the same) and as a want negated, had or past (NOT_WANTED:
    refused). For a grounded entry: a want frame after it for a person and a one-of-a-kind object
    it does not name (the entry's reading and that handover). For an entry saying a person by a
    name with a word after it: an apposition between commas after the name (as the entry, or
    refused with its readings). For an entry of one handover of a one-of-a-kind object to a
    person (session 38): another one-of-a-kind object it does not name given up for its own
    (INSTEAD: the handover). Only forms naming nothing of the scene but their object and person
    are said."""
    text = entry.text.strip()
    want = entry.want

    def fits(form: str) -> bool:
        return _names_nothing(re.sub(r"\{\w\}", "", form), scene)

    def say(form: str, oid: str, hid: str) -> str:
        p = _name(scene, hid)
        return form.format(o=_name(scene, oid), p=p, P=p[:1].upper() + p[1:])

    unique = _unique_objects(scene)
    if (
        isinstance(want, Task)
        and want.kind == "deliver"
        and want.target is not None
        and want.obj in unique
    ):
        for forms, to, form in (
            (WANT_FRAMES, want, "frame"),
            (TOLD, want, "told"),
            (NOT_WANTED, None, "not wanted"),
        ):
            fitting = [f for f in forms if fits(f)]
            if fitting:
                said = say(rng.choice(fitting), want.obj, want.target)
                must: Must = "same" if to is not None else "refuse"
                yield Variant(part, entry.scene, said, to, must, "frames", (), form)
    if want is not None:
        named = _objects_named(text, scene) | {t.obj for t in tasks(want)}
        free = [x for x in unique if x not in named]
        fitting = [f for f in WANT_FRAMES if fits(f)]
        if free and fitting:
            oid, hid = rng.choice(free), rng.choice(scene.humans).id
            added = Task("deliver", oid, hid)
            said = text if text.endswith((".", "!", "?")) else text + "."
            said += " " + say(rng.choice(fitting), oid, hid)
            group = Group("and", (want, added))
            yield Variant(part, entry.scene, said, group, "same", "frames", (), "frame tail", added)
    spots = [
        m
        for m in _people_said(text, scene)
        if (after := re.match(r" ([A-Za-z]+)", text[m.end() :])) and after[1].lower() not in _HELD
    ]
    appositions = [a for a in APPOSITIONS if _names_nothing(a, scene)]
    if spots and appositions:
        m, apposition = rng.choice(spots), rng.choice(appositions)
        said = f"{text[: m.end()]}, {apposition},{text[m.end() :]}"
        must = "same" if want is not None else "refuse"
        yield Variant(part, entry.scene, said, want, must, "frames", entry.readings, "apposition")
    # (session 38) another one-of-a-kind object the entry does not name given up for its own
    if (
        isinstance(want, Task)
        and want.kind == "deliver"
        and want.target is not None
        and want.obj in unique
    ):
        given_up = [x for x in unique if x != want.obj and x not in _objects_named(text, scene)]
        instead = [f for f in INSTEAD if fits(f)]
        if given_up and instead:
            x = _name(scene, rng.choice(given_up))
            said = say(rng.choice(instead).replace("{x}", x), want.obj, want.target)
            yield Variant(part, entry.scene, said, want, "same", "frames", (), "instead")


def _in_list(text: str, at: re.Match[str]) -> bool:
    """Whether the words ``at`` matched may be an item of a list ("the cup, the chips and …")."""
    return bool(_LIST_BEFORE.search(text[: at.start()]) or _LIST_AFTER.match(text[at.end() :]))


# a choice said before the words a repair moves ("one of the cup, ", "any one of the cup or ")
_CHOICE_OPENED = re.compile(
    r"(?i)\b(?:one|any|either)(?: one)? of (?:the )?[\w' -]+?"
    r"(?:(?:,|,? or|,? and) (?:the )?[\w' -]+?)*(?:,|,? or|,? and)\s*$"
)


def _later_in_choice(
    text: str, at: re.Match[str], scene: Scene, kind: Literal["object", "human"]
) -> bool:
    """Whether the words ``at`` matched are a later name of a choice ("the cup or the apple",
    "one of the cup, the apple and …", "Alice or Bob"): a repair of them could replace that name
    only, or the whole choice (session 37, 12s: refused naming both)."""
    before = text[: at.start()]
    if _CHOICE_OPENED.search(before):
        return True
    if not re.search(r"(?i)\bor\s*$", before):
        return False
    prev = re.sub(r"(?i),?\s*\bor\s*$", "", before)
    try:
        items = lex(prev, Lexicon.of(scene))
    except GroundingError:
        return False
    last = next((it for it in reversed(items) if it.kind != "punct" or it.text != ","), None)
    return last is not None and last.kind == "ent" and all(r.kind == kind for r in last.refs)


def _repair(text: str, at: re.Match[str], rng: random.Random) -> str:
    """A form of REPAIRS for the words ``at`` matched: no bare filler in a list."""
    return rng.choice([f for f in REPAIRS if not (f in FILLERS and _in_list(text, at))])


def _said_once(text: str, scene: Scene, oid: str) -> re.Match[str] | None:
    """The one place ``text`` says the object ``oid``, as "the <name>" (any case; not before a
    possessive nor after a negation), where nothing else in it names the object; else None."""
    items = lex(text, Lexicon.of(scene))
    if sum(1 for it in items if it.kind == "ent" and any(r.id == oid for r in it.refs)) != 1:
        return None
    obj = next(o for o in scene.objects if o.id == oid)
    names = sorted({*obj.aliases, oid.replace("_", " ")}, key=len, reverse=True)
    found: list[re.Match[str]] = []
    for name in names:
        for m in re.finditer(rf"(?i)\b(the) ({re.escape(name)})\b(?!['’])", text):
            if _objects_named(m[0], scene) == {oid} and not any(
                f.start() <= m.start() < f.end() for f in found
            ):
                found.append(m)
    if len(found) != 1 or _NEGATED.search(text[: found[0].start()]):
        return None
    return found[0]


def _inserted(text: str, at: re.Match[str], form: str, x: str) -> str:
    """``text`` with the words ``at`` matched said by ``form`` after ``x`` ("{x}, er, {o}"): a
    form that ends in a remark ("…, I forget which") is closed by a comma before more words."""
    said = at[0]
    if said.startswith("The ") and x.startswith("the "):  # (the sentence's first word)
        x, said = "The " + x[4:], "the " + said[4:]
    put = form.format(x=x, o=said)
    rest = text[at.end() :]
    if form.endswith("which") and rest and not re.match(r"\s*[,.!?;]", rest):
        put += ","
    return text[: at.start()] + put + rest


def _proper_name(scene: Scene, hid: str) -> str | None:
    """A name of the person ``hid`` in capitals ("Bob", "Mr Lee") no other shares, or None."""
    h = next(h for h in scene.humans if h.id == hid)
    shared = {a for x in scene.humans if x.id != hid for a in x.aliases}
    return next((n for n in (*h.aliases, h.name) if n[:1].isupper() and n not in shared), None)


def repairs(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The repair variants of one entry. For a grounded entry saying one object it moves once as
    "the <name>": that object said after a one-of-a-kind object the entry does not name and a
    repair (REPAIRS: the entry), and left undecided between the two (UNDECIDED_REPAIRS: refused).
    For a grounded entry of one task saying no pronoun: the other object added before its own with
    "and" (ADDED_REPAIRS: that task of both). For an entry saying a person by a name and no
    pronoun: that name said after another person's the entry does not name and a repair (REPAIRS:
    the entry, or refused with its readings), and a name of two words begun and said again
    (STUTTERS: the same). No bare filler in a list, nothing after a negation (see FILLERS)."""
    text = entry.text.strip()
    want = entry.want
    pronoun = bool(_words(text) & (_PRONOUNS | {"it", "its"}))

    def variant(said: str, to: Node | None, form: str) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, said, to, must, "repairs", entry.readings, form)

    if want is not None:
        named = _objects_named(text, scene) | {t.obj for t in tasks(want)}
        free = [x for x in _unique_objects(scene) if x not in named]
        spots = [
            m for oid in sorted({t.obj for t in tasks(want)}) if (m := _said_once(text, scene, oid))
        ]
        if free and spots:
            at, xid = rng.choice(spots), rng.choice(free)
            x = "the " + _name(scene, xid)
            # a later name of a choice repaired: it, or the whole choice? (refused)
            fixed = None if _later_in_choice(text, at, scene, "object") else want
            yield variant(_inserted(text, at, _repair(text, at, rng), x), fixed, "object")
            yield variant(_inserted(text, at, rng.choice(UNDECIDED_REPAIRS), x), None, "undecided")
            if isinstance(want, Task) and not pronoun:
                both = Group("and", (Task(want.kind, xid, want.target), want))
                yield variant(_inserted(text, at, rng.choice(ADDED_REPAIRS), x), both, "added")
    if pronoun:
        return
    people = _people_said(text, scene)
    said_at = [m for m in people if not _NEGATED.search(text[: m.start()])]
    met = _named(text, scene, "human").union(*(_named(m[0], scene, "human") for m in people))
    others = [q for h in scene.humans if h.id not in met and (q := _proper_name(scene, h.id))]
    if said_at and others:
        at, q = rng.choice(said_at), rng.choice(others)
        fixed = None if _later_in_choice(text, at, scene, "human") else want
        yield variant(_inserted(text, at, _repair(text, at, rng), q), fixed, "person")
    long = [m for m in said_at if " " in m[0]]
    if long:
        at = rng.choice(long)
        yield variant(
            _inserted(text, at, rng.choice(STUTTERS), at[0].split(" ")[0]), want, "stutter"
        )


def _deferred_to(scene: Scene, rng: random.Random) -> str:
    """Who a deferral names: a person of the scene by a name no other shares, or a role naming
    nothing in the scene ("the deckhand")."""
    people = [n for h in scene.humans if (n := _proper_name(scene, h.id))]
    roles = [f"the {r}" for r in ROLES if _names_nothing(f"the {r}", scene)]
    return rng.choice(people + roles if rng.random() < 0.5 or not people else people)


def deferrals(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The deferral variants of one entry: a sentence after it handing on what comes next
    (DEFERRED_AFTER), a clause joined to it (DEFERRED_JOINED; not after a question) and words
    before it (DEFERRED_BEFORE; not before a take-back), each refused; and a sentence closing
    the request (SETTLED): the entry (a refused entry stays refused, with its readings)."""
    text, free = _sentence_and_free(entry, scene)

    def variant(said: str, form: str) -> Variant:
        if form == "settled" and entry.want is not None:
            return Variant(part, entry.scene, said, entry.want, "same", "deferrals", (), form)
        readings = entry.readings if form == "settled" else ()
        return Variant(part, entry.scene, said, None, "refuse", "deferrals", readings, form)

    after = [f for f in DEFERRED_AFTER if free or "{o}" not in f]
    p = _deferred_to(scene, rng)
    o = _name(scene, rng.choice(free)) if free else ""
    form = rng.choice(after).format(p=p, P=p[:1].upper() + p[1:], o=o)
    yield variant(text + form, "after")
    if not text.endswith("?"):
        p = _deferred_to(scene, rng)
        yield variant(text.rstrip(".!") + rng.choice(DEFERRED_JOINED).format(p=p), "joined")
    if not text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry")):
        p = _deferred_to(scene, rng)
        before = rng.choice(DEFERRED_BEFORE).format(p=p)
        body = text if before.endswith(". ") else _after(", ", text, scene)[2:]
        yield variant(before + body, "before")
    yield variant(text + rng.choice(SETTLED), "settled")
    if entry.want is not None and has_choice(entry.want):
        if text.endswith("?") or rng.random() < 0.5:
            said = text + rng.choice(YOURS_AFTER)
        else:
            said = text.rstrip(".!") + rng.choice(YOURS_JOINED)
        yield Variant(part, entry.scene, said, entry.want, "same", "deferrals", (), "yours")
    elif entry.want is not None and len(free) >= 2 and not _has_order(entry.want):
        oid, xid = rng.sample(free, 2)
        hid = rng.choice(scene.humans).id
        choice = Group("or", (Task("deliver", oid, hid), Task("deliver", xid, hid)))
        p = _name(scene, hid)
        said = text + rng.choice(YOURS_ADDED).format(p=p, o=_name(scene, oid), x=_name(scene, xid))
        want = Group("and", (entry.want, choice))
        yield Variant(part, entry.scene, said, want, "same", "deferrals", (), "yours added")


def _has_order(node: Node) -> bool:
    return isinstance(node, Group) and (
        node.op == "seq" or any(_has_order(c) for c in node.children)
    )


def _agreed(o: str) -> dict[str, str]:
    """The verb forms that agree with the object named ``o`` ("the chips are", "the cup is")."""
    plural = o.endswith("s") and not o.endswith("ss")
    return {
        "be": "are" if plural else "is",
        "go": "go" if plural else "goes",
        "it": "them" if plural else "it",
    }


def _surface_name(scene: Scene, sid: str) -> str | None:
    """A name of the surface ``sid`` that names it alone after "the", or None."""
    surface = next(s for s in scene.surfaces if s.id == sid)
    for name in (*surface.aliases, sid.replace("_", " ")):
        if _named(f"the {name}", scene, "surface") == {sid}:
            return name
    return None


def clefts(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The cleft variants of one entry. For a grounded entry of one handover of a one-of-a-kind
    object to a person: that handover said in a cleft (CLEFTS: the handover), with another person
    set against it (CONTRASTS: the same), negated (NOT_CLEFTS: refused), of a person the scene does
    not have (ABSENT in a cleft: refused) and with a second one-of-a-kind object (SECOND: both
    handovers). For a grounded entry: a cleft after it adding a handover of an object it does not
    name (CLEFT_TAILS: the entry's reading and that handover). For an entry of one placement of a
    one-of-a-kind object: the surface in a cleft (PLACE_CLEFTS: the placement). Only forms naming
    nothing of the scene but their objects, people and surface are said."""
    text, free = _sentence_and_free(entry, scene)
    want = entry.want
    unique = _unique_objects(scene)

    def fits(forms: tuple[str, ...]) -> list[str]:
        return [f for f in forms if _names_nothing(re.sub(r"\{\w+\}", "", f), scene)]

    def say(form: str, oid: str, p: str, **more: str) -> str:
        o = _name(scene, oid)
        return form.format(o=o, p=p, P=p[:1].upper() + p[1:], **_agreed(o), **more)

    def variant(said: str, to: Node | None, form: str, added: Task | None = None) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, said, to, must, "clefts", (), form, added)

    if (
        isinstance(want, Task)
        and want.kind == "deliver"
        and want.target is not None
        and want.obj in unique
    ):
        p = _name(scene, want.target)
        cleft = fits(CLEFTS)
        if cleft:
            yield variant(say(rng.choice(cleft), want.obj, p), want, "cleft")
        others = [
            q for h in scene.humans if h.id != want.target and (q := _proper_name(scene, h.id))
        ]
        contrast = fits(CONTRASTS)
        if others and contrast:
            said = say(rng.choice(contrast), want.obj, p, q=rng.choice(others))
            yield variant(said, want, "contrast")
        negated = fits(NOT_CLEFTS)
        if negated:
            yield variant(say(rng.choice(negated), want.obj, p), None, "not")
        absent = [z for z in ABSENT if _names_nothing(z, scene)]
        if cleft and absent:
            yield variant(say(rng.choice(cleft), want.obj, rng.choice(absent)), None, "absent")
        second = fits(SECOND)
        if free and second:
            xid = rng.choice(free)
            said = say(rng.choice(second), want.obj, p, x=_name(scene, xid))
            both = Group("and", (want, Task("deliver", xid, want.target)))
            yield variant(said, both, "second")
    tail = fits(CLEFT_TAILS)
    if want is not None and free and tail:
        oid, hid = rng.choice(free), rng.choice(scene.humans).id
        added = Task("deliver", oid, hid)
        said = text + say(rng.choice(tail), oid, _name(scene, hid))
        yield variant(said, Group("and", (want, added)), "cleft tail", added)
    if isinstance(want, Task) and want.kind == "place" and want.obj in unique:
        s = _surface_name(scene, want.target)
        place = fits(PLACE_CLEFTS)
        if s and place:
            o = _name(scene, want.obj)
            yield variant(rng.choice(place).format(o=o, s=s), want, "place")


def _several(name: str) -> str | None:
    """The plural of an object's name ("apple": "apples", "knife": "knives", "teddy": "teddies"),
    or None for a name already plural, a mass noun or a name with "of" ("bag of crisps")."""
    last = name.rsplit(" ", 1)[-1].lower()
    if last.endswith("s") or last in MASS or " of " in name:
        return None
    if last.endswith("fe"):
        return name[:-2] + "ves"
    if last.endswith("y") and last[-2:-1] not in ("a", "e", "i", "o", "u"):
        return name[:-1] + "ies"
    return _plural(name)


def _counted(n: int, rng: random.Random) -> str:
    """The count ``n`` said as a word or (a third of the time) in digits."""
    return str(n) if rng.randrange(3) == 0 else NUMBERS[n]


def _miscount(n: int, rng: random.Random) -> int:
    """A count of two or more that is not ``n``: one more, or (of three or more) one fewer."""
    return rng.choice((n + 1, n - 1)) if n >= 3 else n + 1


def _of_kind_said(n: int, forms: tuple[str, ...], rng: random.Random) -> str:
    """A form of ``forms`` for a count ``n``: "all {n}" only for three or more."""
    return rng.choice([f for f in forms if n >= 3 or "all {n}" not in f])


def _plurals(scene: Scene) -> dict[str, tuple[str, tuple[str, ...]]]:
    """The kinds the scene has several objects of whose plural the lexer reads as every one
    ("the mugs"), by that plural: the kind and its ids."""
    kinds, _ = _shared(scene)
    return {
        _plural(c): (c, ids)
        for c, ids in kinds.items()
        if _named(f"the {_plural(c)}", scene, "object") == set(ids)
    }


# a word before "the <kinds>" after which no count can be said ("one of the mugs", "all the mugs")
_NO_COUNT_AFTER = re.compile(
    r"(?i)\b(?:of|all|both|any|either|neither|each|every|" + "|".join(NUMBERS) + r"|\d+)\s+$"
)


def _the_once(text: str, name: str) -> re.Match[str] | None:
    """The one "the <name>" of ``text`` (a whole word, "The" at a sentence's start), or None."""
    found = list(re.finditer(rf"\b([Tt]he) {re.escape(name)}(?![\w'-])", text))
    return found[0] if len(found) == 1 else None


def counts(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The count variants of one entry. For a scene with a kind it has several objects of, a
    request of every one of the kind for a person with the count (KIND_COUNTS, BOTH for two:
    every one to that person) or another count (BOTH for three or more: refused), and (session
    38) one of the kind, any one (ANY_OF: a choice of each to that person). For a grounded
    entry with no choice in it naming its one one-of-a-kind object once as "the <name>", that
    object said as the only one (ONE: the entry) or as several (SEVERAL: refused); naming a kind
    in the plural once as "the <kinds>" (every one of the kind) and nothing else of that kind, that
    plural said with its count or "both" (the entry) and with another count (refused)."""
    text = entry.text.strip()
    want = entry.want
    plurals = _plurals(scene)

    def variant(said: str, to: Node | None, form: str) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, said, to, must, "counts", (), form)

    if plurals:
        cs, (_, ids) = rng.choice(sorted(plurals.items()))
        hid = rng.choice(scene.humans).id
        p = _name(scene, hid)
        every = Group("and", tuple(Task("deliver", i, hid) for i in ids))
        n, agree = len(ids), rng.randrange(2) == 0
        if agree:
            forms = KIND_COUNTS + BOTH if n == 2 else KIND_COUNTS
        else:
            forms = KIND_COUNTS + BOTH if n >= 3 else KIND_COUNTS
            n = _miscount(n, rng)
        form = _of_kind_said(n, forms, rng)
        said = form.format(p=p, P=p[:1].upper() + p[1:], n=_counted(n, rng), cs=cs)
        yield variant(said, every if agree else None, "kind" if agree else "kind miscounted")
        # (session 38) one of a kind, any one
        cs, (c, ids) = rng.choice(sorted(plurals.items()))
        hid = rng.choice(scene.humans).id
        p = _name(scene, hid)
        said = rng.choice(ANY_OF).format(p=p, P=p[:1].upper() + p[1:], c=c, cs=cs)
        yield variant(said, Group("or", tuple(Task("deliver", i, hid) for i in ids)), "any")
    if want is None or has_choice(want):
        return
    named = _objects_named(text, scene)
    unique = _unique_objects(scene)
    for oid in sorted({t.obj for t in tasks(want)} & named & set(unique)):
        m = _said_once(text, scene, oid)
        if m is None:
            continue
        the, name, before, after = m[1], m[2], text[: m.start()], text[m.end() :]
        os = _several(name)
        if os is None:  # ("the one chips", "the one salt": no English)
            continue
        one = rng.choice(ONE).format(o=name)
        yield variant(before + the + one[3:] + after, want, "one")
        if _named(f"the {os}", scene, "object") == {oid}:
            many = rng.choice(SEVERAL).format(os=os)
            many = many[:1].upper() + many[1:] if the[:1].isupper() else many
            yield variant(before + many + after, None, "several")
        break
    for cs, (kind, ids) in sorted(plurals.items()):
        m = _the_once(text, cs)
        if m is None or _NO_COUNT_AFTER.search(text[: m.start()]):
            continue
        rest = text[: m.start()] + text[m.end() :]
        # (nor where the rest may narrow the kind: "both pens … apart from the black one" says
        # two of three, as a careful person reads it)
        telling = {w for o in scene.objects if o.id in ids for w in _words(" ".join(o.aliases))}
        narrows = _TELLING | {"one", "ones"} | (telling - _words(kind))
        if _named(rest, scene, "object") & set(ids) or _words(rest) & narrows:
            continue
        n = len(ids)
        # (a list after a colon says what is meant: "all the kit except both boxes: that's the
        # scanner, the tape and the gloves" is those three, as a careful person reads it, so no
        # other count is said there)
        for agree in (True,) if ":" in text[m.end() :] else (True, False):
            forms = (*ENTRY_COUNTS, *ENTRY_BOTH) if (n == 2) is agree else ENTRY_COUNTS
            count = n if agree else _miscount(n, rng)
            form = _of_kind_said(count, forms, rng).format(n=_counted(count, rng), cs=cs)
            form = form[:1].upper() + form[1:] if m[1] == "The" else form
            said = text[: m.start()] + form + text[m.end() :]
            to = want if agree else None
            yield variant(said, to, "entry" if agree else "entry miscounted")


def remarks(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The remark variants of one entry: a remark naming nothing of the scene after it (REMARKS:
    as the entry, or refused; a refused entry stays refused with its readings), a delay after it
    (TIMED: refused), for a grounded entry of one handover naming its one person by a name and
    no other person or object (and no pronoun for a person), that person said not to want it
    (CONTRARY: refused), and, for a grounded entry with no pronoun for a person, a remark about a
    person of the scene said by a name no other shares (CONTEXT: the entry, or refused); session
    38: for an entry of one handover naming its one person (as CONTRARY), a remark about a person
    by a pronoun after it (ABOUT: the entry, or refused), and, for a grounded entry with no
    pronoun for a person that takes nothing back, a remark about a person by a name before it
    (CONTEXT_BEFORE: the entry, or refused). After a question only the ". " forms."""
    text = entry.text.strip()
    question = text.endswith("?")

    def said(forms: tuple[str, ...]) -> list[str]:  # (CONTRARY's person left out)
        plain = [f for f in forms if not question or f.startswith(". ")]
        return [f for f in plain if _names_nothing(re.sub(r"\{[pP]\}", "", f), scene)]

    def variant(form: str, to: Node | None, readings: tuple[str, ...], name: str) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, _then(text, form), to, must, "remarks", readings, name)

    if forms := said(REMARKS):
        yield variant(rng.choice(forms), entry.want, entry.readings, "remark")
    if forms := said(TIMED):
        yield variant(rng.choice(forms), None, (), "time")
    one = _one_person_said(text, entry.want, scene)
    if one is not None and (forms := said(CONTRARY)):
        p = one[0]
        yield variant(rng.choice(forms).format(p=p, P=p[:1].upper() + p[1:]), None, (), "contrary")
    names = [n for h in scene.humans if (n := _proper_name(scene, h.id)) is not None]
    grounded = entry.want is not None and not _words(text) & _PRONOUNS
    if grounded and names and (forms := said(CONTEXT)):
        p = rng.choice(names)
        yield variant(rng.choice(forms).format(p=p, P=p), entry.want, entry.readings, "context")
    # (session 38)
    about = [
        f
        for f in ABOUT
        if (not question or f.startswith(". ")) and _names_nothing(re.sub(r"\{\w+\}", "", f), scene)
    ]
    if one is not None and about:
        fill = rng.choice(PRONOUN_SETS)
        big = {k[:1].upper() + k[1:]: w[:1].upper() + w[1:] for k, w in fill.items()}
        yield variant(rng.choice(about).format(**fill, **big), entry.want, (), "about")
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    before = [f for f in CONTEXT_BEFORE if _names_nothing(f.replace("{P}", ""), scene)]
    if grounded and names and before and not takes_back:
        p = rng.choice(names)
        said_before = _after(rng.choice(before).format(P=p), text, scene)
        yield Variant(
            part, entry.scene, said_before, entry.want, "same", "remarks", (), "context before"
        )


# words that point back or take back: no remark sentence goes before a sentence saying one (MIDDLE)
_POINTING39 = frozenset(
    [
        *_PRONOUNS,
        *("it", "its", "that", "this", "those", "these", "one", "ones", "other", "others"),
        *("same", "rest", "there", "either", "no", "not", "sorry", "actually", "instead"),
        *("rather", "mean", "meant", "correction", "scratch", "forget", "never", "wait", "oops"),
        "cancel",
    ]
)
_SENTENCE_END39 = re.compile(
    r"(?<!\bMr\.)(?<!\bMrs\.)(?<!\bMs\.)(?<!\bDr\.)(?<!\bSt\.)(?<=[.!?])\s+(?=[A-Z])"
)
_JOINING39 = ("so ", "and ", "but ", "then ", "also ", "or ")


def remarks39(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """Session 39's remark variants of one entry (REMARK_FORMS39, drawn from their own generator
    so that a seed's earlier remarks stay as they were): by a pronoun before an entry of one
    handover naming its one person (ABOUT_BEFORE), by a possessive after it (POSSESSIVE), by a
    name's possessive after a grounded entry with no pronoun for a person (POSSESSIVE_NAMED), by
    "we" and about the place after and before any entry (WE, WE_BEFORE, PLACE, PLACE_BEFORE; not
    before an entry that takes back, nor joined by "so" to one opening with a joining word), a
    sentence between two of an entry's sentences of three words or more, the rest saying no word
    that points or takes back (MIDDLE), and a clause after a name inside a grounded entry with
    no pronoun for a person (WHO): the entry, or refused (a refused entry stays refused with its
    readings). After a question only the ". " forms."""
    text = entry.text.strip()
    question = text.endswith("?")
    grounded = entry.want is not None and not _words(text) & _PRONOUNS
    one = _one_person_said(text, entry.want, scene)
    names = [n for h in scene.humans if (n := _proper_name(scene, h.id)) is not None]
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    joined = text.lower().startswith(_JOINING39)
    fills = [
        {**fill, **{k[:1].upper() + k[1:]: w[:1].upper() + w[1:] for k, w in fill.items()}}
        for fill in PRONOUN_SETS
    ]

    def fitting(forms: tuple[str, ...], after: bool) -> list[str]:
        plain = [f for f in forms if not after or not question or f.startswith(". ")]
        plain = [f for f in plain if after or not joined or f.endswith(". ")]
        return [f for f in plain if _names_nothing(re.sub(r"\{\w+\}", "", f), scene)]

    def variant(said: str, to: Node | None, readings: tuple[str, ...], form: str) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, said, to, must, "remarks", readings, form)

    if one is not None and not takes_back and (forms := fitting(ABOUT_BEFORE, False)):
        said = _after(rng.choice(forms).format(**rng.choice(fills)), text, scene)
        yield variant(said, entry.want, (), "about before")
    if one is not None and (forms := fitting(POSSESSIVE, True)):
        said = _then(text, rng.choice(forms).format(**rng.choice(fills)))
        yield variant(said, entry.want, (), "possessive")
    if grounded and names and (forms := fitting(POSSESSIVE_NAMED, True)):
        p = rng.choice(names)
        said = _then(text, rng.choice(forms).format(p=p, P=p))
        yield variant(said, entry.want, (), "possessive by name")
    for after, before, form in ((WE, WE_BEFORE, "we"), (PLACE, PLACE_BEFORE, "place")):
        if forms := fitting(after, True):
            yield variant(_then(text, rng.choice(forms)), entry.want, entry.readings, form)
        if not takes_back and (forms := fitting(before, False)):
            said = _after(rng.choice(forms), text, scene)
            yield variant(said, entry.want, entry.readings, form + " before")
    cuts = [
        m.start()
        for m in _SENTENCE_END39.finditer(text)
        if len(text[: m.start()].split()) >= 3
        and len(text[m.end() :].split()) >= 3
        and not _words(text[m.end() :]) & _POINTING39
    ]
    middle = [f for f in MIDDLE if "{P}" not in f or names]
    if cuts and (forms := fitting(tuple(middle), True)):
        at = rng.choice(cuts)
        p = rng.choice(names) if names else ""
        form = rng.choice(forms)
        said = f"{text[:at]} {form.format(P=p)}{text[at:]}"
        # a remark about a person before a sentence naming no person of its own could give that
        # sentence its person ("Give Bob the chips. Alice's bus was late. The apple too.": Bob's,
        # or Alice's?), so it is not made (the draws stay as they were)
        after = _SENTENCE_END39.split(text[at:].lstrip(), maxsplit=1)[0]
        if "{P}" not in form or _named(after, scene, "human"):
            yield variant(said, entry.want, entry.readings, "middle")
    inside = [m for m in _people_said(text, scene) if re.match(r" [A-Za-z]", text[m.end() :])]
    if grounded and inside and (forms := [f for f in WHO if _names_nothing(f, scene)]):
        m = rng.choice(inside)
        said = text[: m.end()] + rng.choice(forms) + text[m.end() :]
        yield variant(said, entry.want, (), "who")


def _scene_words(scene: Scene) -> set[str]:
    """The words of every name of an object, person or surface of ``scene`` (lower case)."""
    names = [
        *(n for o in scene.objects for n in (o.id.replace("_", " "), o.category, *o.aliases)),
        *(n for h in scene.humans for n in (h.name, *h.aliases)),
        *(n for s in scene.surfaces for n in (s.id.replace("_", " "), *s.aliases)),
    ]
    return {w for n in names for w in re.findall(r"[a-z]+", n.lower())}


def _purpose_after(text: str, phrase: str, scene: Scene, comma: bool) -> str | None:
    """``text`` with ``phrase`` ("for <purpose>") at its end, before its last stop or question
    mark, after a comma or not; without a comma only after a word of a name of ``scene`` (not
    after "please", "too", a remark …), else None."""
    bare = text.rstrip(".!?")
    end = text[len(bare) :] or "."
    if not comma:
        said = re.findall(r"[A-Za-z]+", bare)
        if not said or said[-1].lower() not in _scene_words(scene):
            return None
    return f"{bare}{',' if comma else ''} {phrase}{end}"


# what may follow an object for a purpose to be said after it inside an entry
_PURPOSE_INSIDE = re.compile(r"(?i)^(?:,|\s+(?:to|on|onto|in|into|over to|please)\b)")


def _pronoun_of(name: str) -> str | None:
    """The possessive ("his" or "her") of a name NAMED_HE / NAMED_SHE says, else None."""
    return "his" if name in NAMED_HE else "her" if name in NAMED_SHE else None


def purposes(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The purpose variants of one entry (PURPOSE_FORMS): a purpose naming nothing of the scene
    (an event or a group) said after it with or without a comma (not without one after a word
    that names nothing of the scene), before it (not before one that takes back or opens with a
    joining word), after its one object inside an entry of one task, and as a sentence after it:
    the entry, or refused (a refused entry stays refused with its readings); for an entry of one
    handover naming its one person, "his/her/their <pastime>" after it fitting that person
    (`possessive`) or fitting another person of the scene and not that one (`possessive other`):
    the entry, or refused; and, for a grounded entry, one of its objects with a purpose as its
    only recipient (`only`) and the entry said after it to be for a later time (`time`): refused.
    After a question only the sentence forms follow it."""
    text = entry.text.strip()
    question = text.endswith("?")
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    joined = text.lower().startswith(_JOINING39)
    events = [x for x in PURPOSE_EVENTS if _names_nothing(x, scene)]
    groups = [x for x in PURPOSE_GROUPS if _names_nothing(x, scene)]
    own = [x for x in PURPOSE_OWN if _names_nothing(x, scene)]
    if not events or not groups or not own:
        return
    want = entry.want

    def purpose() -> str:
        return rng.choice(events if rng.random() < 0.5 else groups)

    def said_after(phrase: str, comma: bool) -> str:
        said = _purpose_after(text, phrase, scene, comma) or _purpose_after(
            text, phrase, scene, True
        )
        assert said is not None  # (with a comma, always)
        return said

    def variant(said: str, form: str, refused: bool = False) -> Variant:
        if refused:
            return Variant(part, entry.scene, said, None, "refuse", "purposes", (), form)
        must: Must = "same" if want is not None else "refuse"
        return Variant(part, entry.scene, said, want, must, "purposes", entry.readings, form)

    if (said := _purpose_after(text, f"for {purpose()}", scene, comma=False)) is not None:
        yield variant(said, "after")
    yield variant(said_after(f"for {purpose()}", True), "after comma")
    x = purpose()
    if not takes_back and not joined:
        yield variant(_after(f"For {x}, ", text, scene), "before")
    if isinstance(want, Task) and (at := _said_once(text, scene, want.obj)) is not None:
        x = purpose()
        if _PURPOSE_INSIDE.match(text[at.end() :]):
            yield variant(f"{text[: at.end()]} for {x}{text[at.end() :]}", "inside")
    yield variant(_then(text, rng.choice(PURPOSE_SENTENCES).format(x=purpose())), "sentence")
    one = _one_person_said(text, want, scene)
    if one is not None:
        name, task = one
        fits = _pronoun_of(name)
        pos = rng.choice((fits, "their")) if fits is not None else "their"
        yield variant(said_after(f"for {pos} {rng.choice(own)}", rng.random() < 0.5), "possessive")
        other = {"his": "her", "her": "his"}.get(fits or "")
        elsewhere = [
            h.id
            for h in scene.humans
            if h.id != task.target and any(_pronoun_of(n) == other for n in (h.name, *h.aliases))
        ]
        if other is not None and elsewhere:
            phrase = f"for {other} {rng.choice(own)}"
            yield variant(said_after(phrase, rng.random() < 0.5), "possessive other")
    if want is not None:
        unique = _unique_objects(scene)
        moved = [t.obj for t in tasks(want) if t.obj in unique]
        if moved or unique:
            o = _name(scene, rng.choice(moved or unique))
            if rng.random() < 0.25:
                x = f"{rng.choice(('his', 'her', 'their'))} {rng.choice(own)}"
            else:
                x = purpose()
            said = rng.choice(PURPOSE_ONLY).format(o=o, O=o[:1].upper() + o[1:], x=x)
            yield variant(said, "only", refused=True)
        times = [f for f in PURPOSE_TIMES if not question or f.startswith(". ")]
        yield variant(_then(text, rng.choice(times)), "time", refused=True)


def _fits(form: str, scene: Scene) -> bool:
    """Whether ``form`` names nothing of ``scene`` but what its keys ({o}, {p} …) say."""
    return _names_nothing(re.sub(r"\{\w+\}", "", form), scene)


def idioms(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The idiom variants of one grounded entry (IDIOM_FORMS; none of a refused one). For an entry
    of one handover of a one-of-a-kind object to a person: that handover said by a want idiom
    (`want`: the handover), the want taken back alone and after the entry (`cancelled`,
    `cancelled after`: refused) and the object left to the robot between that person and another
    (`choice person`: that choice). For any grounded entry: a want idiom after it for a
    one-of-a-kind object it does not name (`want tail`: the entry and that handover), a choice
    left to the robot between two one-of-a-kind objects for a person (`choice`; the entry's own
    object and person where it has one handover of a one-of-a-kind object), between the objects of
    a kind the scene has several of (`choice kind`) and of a kind it lacks (`choice absent`:
    refused), and an exclusion idiom of one of a kind the scene tells apart (`exclusion`: every
    other one of it) and of one one-of-a-kind object from everything (`exclusion all`: every
    other object of the scene). Only forms naming nothing of the scene but their keys are said."""
    want = entry.want
    if want is None:
        return
    text = entry.text.strip()

    def variant(said: str, to: Node | None, form: str, added: Task | None = None) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        return Variant(part, entry.scene, said, to, must, "idioms", (), form, added)

    def say(forms: tuple[str, ...], **keys: str) -> str | None:
        fitting = [f for f in forms if _fits(f, scene)]
        if not fitting:
            return None
        if "p" in keys:
            keys["P"] = keys["p"][:1].upper() + keys["p"][1:]
        said = rng.choice(fitting).format(**keys)
        return said[:1].upper() + said[1:]

    unique = _unique_objects(scene)
    one = (
        want
        if isinstance(want, Task)
        and want.kind == "deliver"
        and want.target is not None
        and want.obj in unique
        else None
    )
    if one is not None and one.target is not None:
        o, p = _name(scene, one.obj), _name(scene, one.target)
        if (said := say(WANT_IDIOMS, o=o, p=p)) is not None:
            yield variant(said, one, "want")
        if (said := say(CANCELLED, o=o, p=p)) is not None:
            yield variant(said, None, "cancelled")
        if (said := say(CANCELLED, o=o, p=p)) is not None:
            sentence = text if text.endswith((".", "!", "?")) else text + "."
            yield variant(f"{sentence} {said}", None, "cancelled after")
        others = [h.id for h in scene.humans if h.id != one.target]
        if others:
            q = rng.choice(others)
            if (said := say(CHOICE_PERSON, o=o, p=p, q=_name(scene, q))) is not None:
                to = Group("or", (one, Task("deliver", one.obj, q)))
                yield variant(said, to, "choice person")
    text_said, free = _sentence_and_free(entry, scene)
    if free:
        oid, hid = rng.choice(free), rng.choice(scene.humans).id
        said = say(WANT_IDIOMS, o=_name(scene, oid), p=_name(scene, hid))
        if said is not None:
            added = Task("deliver", oid, hid)
            yield variant(f"{text_said} {said}", Group("and", (want, added)), "want tail", added)
    if len(unique) >= 2:
        if one is not None and one.target is not None:
            oid, hid = one.obj, one.target
            xid = rng.choice([u for u in unique if u != oid])
        else:
            oid, xid = rng.sample(unique, 2)
            hid = rng.choice(scene.humans).id
        o, x, p = _name(scene, oid), _name(scene, xid), _name(scene, hid)
        if (said := say(CHOICE_IDIOMS, o=o, x=x, p=p)) is not None:
            to = Group("or", (Task("deliver", oid, hid), Task("deliver", xid, hid)))
            yield variant(said, to, "choice")
    plurals = _plurals(scene)
    if plurals:
        cs, (c, ids) = rng.choice(sorted(plurals.items()))
        hid = rng.choice(scene.humans).id
        if (said := say(CHOICE_KIND, c=c, cs=cs, p=_name(scene, hid))) is not None:
            yield variant(
                said, Group("or", tuple(Task("deliver", i, hid) for i in ids)), "choice kind"
            )
    absent = [a for a in ABSENT_KINDS if _names_nothing(f"{a} {_plural(a)}", scene)]
    if absent:
        a, hid = rng.choice(absent), rng.choice(scene.humans).id
        keys = {"a": a, "plural": _plural(a), "p": _name(scene, hid)}
        if (said := say(CHOICE_ABSENT, **keys)) is not None:
            yield variant(said, None, "choice absent")
    told = _told_apart(scene)
    if told:
        c, cs, ids, words = rng.choice(told)
        oid = rng.choice(sorted(words))
        hid = rng.choice(scene.humans).id
        said = say(EXCLUSION, c=c, cs=cs, x=words[oid], p=_name(scene, hid))
        if said is not None:
            rest = tuple(Task("deliver", i, hid) for i in ids if i != oid)
            yield variant(said, rest[0] if len(rest) == 1 else Group("and", rest), "exclusion")
    if unique and 2 < len(scene.objects) <= 8:
        oid, hid = rng.choice(unique), rng.choice(scene.humans).id
        said = say(EXCLUSION_ALL, o=_name(scene, oid), p=_name(scene, hid))
        if said is not None:
            rest = tuple(Task("deliver", b.id, hid) for b in scene.objects if b.id != oid)
            yield variant(said, Group("and", rest), "exclusion all")


def _request_said(text: str) -> str | None:
    """An entry that is one request from its verb ("Give Bob the apple, please.") said from its
    verb in lower case without its stop ("give Bob the apple, please"), or None."""
    bare = text.strip().rstrip(".!")
    if re.search(r"[.!?;:]", bare) or bare.split(" ", 1)[0].lower() not in _IMPERATIVE:
        return None
    return bare[:1].lower() + bare[1:]


def _listed(words: list[str]) -> str:
    """ "the red one and the blue one", "the red one, the blue one and the green one"."""
    said = [f"the {w} one" for w in words]
    return ", ".join(said[:-1]) + " and " + said[-1]


def _typo(text: str, scene: Scene, rng: random.Random) -> str | None:
    """``text`` with two letters inside one of its words of five letters or more swapped ("isn't
    meant" as "isn't maent"), a word naming nothing of the scene (none beginning as one of its
    names' words does), or None where it has no such word."""
    names = {
        w.lower()[:4]
        for x in (*scene.objects, *scene.humans, *scene.surfaces)
        for n in (x.id, *x.aliases, getattr(x, "name", ""), getattr(x, "category", ""))
        for w in re.findall(r"[A-Za-z]+", n)
    }
    spots = [
        (m.start() + i, m[0])
        for m in re.finditer(r"[A-Za-z]{5,}", text)
        if m[0].lower()[:4] not in names
        for i in range(1, len(m[0]) - 2)
        if m[0][i] != m[0][i + 1]
    ]
    if not spots:
        return None
    at, _ = rng.choice(spots)
    return text[:at] + text[at + 1] + text[at] + text[at + 2 :]


def turns(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The turn variants of one grounded entry (TURN_FORMS; none of a refused one): negations and
    exclusions, corrections and courtesy question forms said by idioms blind40 does not use. For
    an entry of one handover of a one-of-a-kind object to a person: that handover said with
    another object not for that person (`not for`), not needed (`need instead`), two others
    neither (`neither`), another person not the one (`not theirs`), proposed and agreed to
    (`proposal`): the handover; proposed and dropped (`proposal dropped`), only asked whether
    (`whether`): refused; and, where the entry names no other object, the object corrected
    (`object fixed`: the other object's handover), the person corrected where it names no other
    person (`person fixed`: the handover to them), another object that could replace or add
    (`replace or add`: refused, both objects as readings) and a correction to a kind the scene
    lacks (`fixed absent`: refused). For any grounded entry that is one request from its verb:
    asked as a courtesy (`courtesy`: the entry). For any grounded entry, requests of the scene:
    everything but one object (`everything but`: every other object), the one of a kind of two
    that is not the one named (`the other`), of a kind of three or more (`several left`: refused,
    the rest as readings) and every one of a kind left out (`nothing left`: refused). Then one
    variant that must read, all in lower case (`lower`), and one with a typo (`typo`: two letters
    swapped inside a word naming nothing of the scene): as it must. Only forms naming nothing of
    the scene but their keys are said."""
    want = entry.want
    if want is None:
        return
    text = entry.text.strip()
    made: list[Variant] = []

    def variant(said: str, to: Node | None, form: str, readings: tuple[str, ...] = ()) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        v = Variant(part, entry.scene, said, to, must, "turns", readings, form)
        made.append(v)
        return v

    def say(forms: tuple[str, ...], **keys: str) -> str | None:
        fitting = [f for f in forms if _fits(f, scene)]
        if not fitting:
            return None
        for k in ("p", "q"):
            if k in keys:
                keys[k.upper()] = keys[k][:1].upper() + keys[k][1:]
        said = rng.choice(fitting).format(**keys)
        return said[:1].upper() + said[1:]

    unique = _unique_objects(scene)
    one = (
        want
        if isinstance(want, Task)
        and want.kind == "deliver"
        and want.target is not None
        and want.obj in unique
        else None
    )
    absent = [a for a in ABSENT_KINDS if _names_nothing(f"{a} {_plural(a)}", scene)]
    if one is not None and one.target is not None:
        oid, hid = one.obj, one.target
        o, p = _name(scene, oid), _name(scene, hid)
        others = [u for u in unique if u != oid]
        people = [h.id for h in scene.humans if h.id != hid]
        if others:
            x = _name(scene, rng.choice(others))
            if (said := say(NOT_FOR, o=o, p=p, x=x)) is not None:
                yield variant(said, one, "not for")
            x = _name(scene, rng.choice(others))
            if (said := say(NEED_INSTEAD, o=o, p=p, x=x)) is not None:
                yield variant(said, one, "need instead")
        if len(others) >= 2:
            x, y = (_name(scene, i) for i in rng.sample(others, 2))
            if (said := say(NEITHER, o=o, p=p, x=x, y=y)) is not None:
                yield variant(said, one, "neither")
        if people:
            q = _name(scene, rng.choice(people))
            if (said := say(NOT_THEIRS, o=o, p=p, q=q)) is not None:
                yield variant(said, one, "not theirs")
        if (said := say(PROPOSALS, o=o, p=p)) is not None:
            yield variant(said, one, "proposal")
        if (said := say(PROPOSALS_DROPPED, o=o, p=p)) is not None:
            yield variant(said, None, "proposal dropped")
        if (said := say(WHETHER, o=o, p=p)) is not None:
            yield variant(said, None, "whether")
        bare = text.rstrip(".!")
        if not text.endswith("?") and _objects_named(text, scene) <= {oid}:
            if others:
                xid = rng.choice(others)
                fixed = Task("deliver", xid, hid)
                if (said := say(OBJECT_FIXED, x=_name(scene, xid))) is not None:
                    yield variant(bare + said, fixed, "object fixed")
            if people and _named(text, scene, "human") <= {hid}:
                qid = rng.choice(people)
                if (said := say(PERSON_FIXED, p=p, q=_name(scene, qid))) is not None:
                    yield variant(bare + said, Task("deliver", oid, qid), "person fixed")
            if others:
                xid = rng.choice(others)
                if (said := say(REPLACE_OR_ADD, x=_name(scene, xid))) is not None:
                    yield variant(bare + said, None, "replace or add", (oid, xid))
            if absent and (said := say(FIXED_ABSENT, a=rng.choice(absent))) is not None:
                yield variant(bare + said, None, "fixed absent")
    request = _request_said(text)
    if request is not None and (said := say(COURTESIES, v=request)) is not None:
        yield variant(said, want, "courtesy")
    if unique and 2 < len(scene.objects) <= 8:
        oid, hid = rng.choice(unique), rng.choice(scene.humans).id
        said = say(EVERYTHING_BUT, o=_name(scene, oid), p=_name(scene, hid))
        if said is not None:
            rest = tuple(Task("deliver", b.id, hid) for b in scene.objects if b.id != oid)
            yield variant(said, Group("and", rest), "everything but")
    told = _told_apart(scene)
    if told:
        c, cs, ids, words = rng.choice(told)
        xid = rng.choice(sorted(words))
        hid = rng.choice(scene.humans).id
        said = say(THE_OTHER, c=c, x=words[xid], p=_name(scene, hid))
        rest_ids = tuple(i for i in ids if i != xid)
        if said is not None and len(rest_ids) == 1:
            yield variant(said, Task("deliver", rest_ids[0], hid), "the other")
        elif said is not None:
            yield variant(said, None, "several left", rest_ids)
        if len(words) == len(ids):
            xs = _listed([words[i] for i in ids])
            said = say(EXCLUDED_ALL, c=c, cs=cs, xs=xs, p=_name(scene, rng.choice(scene.humans).id))
            if said is not None:
                yield variant(said, None, "nothing left")
    reading = [v for v in made if v.must == "same"]
    if reading:
        v = rng.choice(reading)
        yield Variant(part, entry.scene, v.text.lower(), v.want, "same", "turns", (), "lower")
        v = rng.choice(reading)
        if (typo := _typo(v.text, scene, rng)) is not None:
            yield Variant(part, entry.scene, typo, v.want, "same", "turns", (), "typo")


def _people_listed(names: list[str]) -> str:
    """ "Alice and Bob", "Alice, Bob and Carol"."""
    return ", ".join(names[:-1]) + " and " + names[-1]


def _dealt(ids: tuple[str, ...], people: tuple[str, ...]) -> Node:
    """Each of ``people`` one of ``ids``, a different one each: every way it can be done, as a
    choice (one way alone where there is one)."""
    ways = tuple(
        Group("and", tuple(Task("deliver", o, h) for o, h in zip(way, people, strict=True)))
        for way in permutations(ids, len(people))
    )
    return ways[0] if len(ways) == 1 else Group("or", ways)


def said_around(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The said variants of one grounded entry (SAID_FORMS; none of a refused one): a request
    framed the way people say it, by words blind41 does not use. For an entry of one handover to
    a person: a reason or state of that person said before it (`reason before`: the entry); of a
    one-of-a-kind object, that handover hung on a condition about others' claims (`condition`:
    the handover) or on an outside event or a later word (`condition outside`: refused), said
    as a want by a comparison or hyperbole (`hyperbole`: the handover) and said against
    (`hyperbole against`: refused). For any grounded entry, requests
    of the scene: a kind the scene has several of dealt out with 'apiece' / 'each' (`apiece`) or
    as "one for P and one for Q" (`one for`): each person a different one, every way as a choice;
    two one-of-a-kind objects to two people 'respectively' (`respectively`): in that order; a
    distribution the scene cannot satisfy (`apiece short`, `respectively short`): refused; a
    one-of-a-kind object back to its owner (`owner`) or someone's object to another person
    (`owner other`): that handover; and an owner that could be either of two people (`owner
    either`): refused, both as readings. Then one variant that must read in lower case (`lower`)
    and one with a typo (`typo`): as it must. Only forms naming nothing of the scene but their
    keys are said."""
    want = entry.want
    if want is None:
        return
    text = entry.text.strip()
    made: list[Variant] = []

    def variant(said: str, to: Node | None, form: str, readings: tuple[str, ...] = ()) -> Variant:
        must: Must = "same" if to is not None else "refuse"
        v = Variant(part, entry.scene, said, to, must, "said", readings, form)
        made.append(v)
        return v

    def say(forms: tuple[str, ...], **keys: str) -> str | None:
        fitting = [f for f in forms if _fits(f, scene)]
        if not fitting:
            return None
        for k in ("p", "q", "ps"):
            if k in keys:
                keys[k[:1].upper() + k[1:]] = keys[k][:1].upper() + keys[k][1:]
        said = rng.choice(fitting).format(**keys)
        return said[:1].upper() + said[1:]

    unique = _unique_objects(scene)
    humans = [h.id for h in scene.humans]
    one = (
        want
        if isinstance(want, Task) and want.kind == "deliver" and want.target is not None
        else None
    )
    if one is not None and one.target is not None:
        p = _name(scene, one.target)
        fitting = [f for f in REASONS_BEFORE if _fits(f, scene)]
        if fitting:
            reason = rng.choice(fitting).format(p=p, P=p[:1].upper() + p[1:])
            yield variant(
                _after(reason[:1].upper() + reason[1:], text, scene), want, "reason before"
            )
        if one.obj in unique:
            o = _name(scene, one.obj)
            if (said := say(CONDITIONS, o=o, p=p)) is not None:
                yield variant(said, one, "condition")
            if (said := say(CONDITIONS_OUTSIDE, o=o, p=p)) is not None:
                yield variant(said, None, "condition outside")
            if (said := say(HYPERBOLES, o=o, p=p)) is not None:
                yield variant(said, one, "hyperbole")
            if (said := say(HYPERBOLES_AGAINST, o=o, p=p)) is not None:
                yield variant(said, None, "hyperbole against")
    plurals = _plurals(scene)
    if plurals and len(humans) >= 2:
        cs, (c, ids) = rng.choice(sorted(plurals.items()))
        k = rng.choice([n for n in (2, 3) if n <= min(len(humans), len(ids))])
        people = tuple(rng.sample(humans, k))
        ps = _people_listed([_name(scene, h) for h in people])
        a = "an" if c[:1] in "aeiou" else "a"
        if (said := say(APIECE, ps=ps, c=c, a=a)) is not None:
            yield variant(said, _dealt(ids, people), "apiece")
        if len(ids) in (2, 3) and len(ids) <= len(humans):
            people = tuple(rng.sample(humans, len(ids)))
            each = _people_listed([f"one for {_name(scene, h)}" for h in people])
            if (said := say(ONE_FOR, cs=cs, each=each)) is not None:
                yield variant(said, _dealt(ids, people), "one for")
        if len(humans) > len(ids):
            people = tuple(rng.sample(humans, len(ids) + 1))
            ps = _people_listed([_name(scene, h) for h in people])
            if (said := say(APIECE, ps=ps, c=c, a=a)) is not None:
                yield variant(said, None, "apiece short")
    alone = [
        o.category
        for o in scene.objects
        if o.id in unique
        and _named(f"the {o.category}", scene, "object") == {o.id}
        and _several(o.category) is not None
    ]
    if alone and len(humans) >= 2:
        c = rng.choice(alone)
        ps = _people_listed([_name(scene, h) for h in rng.sample(humans, 2)])
        a = "an" if c[:1] in "aeiou" else "a"
        if (said := say(APIECE, ps=ps, c=c, a=a)) is not None:
            yield variant(said, None, "apiece short")
    if len(unique) >= 2 and len(humans) >= 2:
        xid, yid = rng.sample(unique, 2)
        pid, qid = rng.sample(humans, 2)
        keys = {"x": _name(scene, xid), "y": _name(scene, yid)}
        keys |= {"p": _name(scene, pid), "q": _name(scene, qid)}
        if (said := say(RESPECTIVELY, **keys)) is not None:
            to = Group("and", (Task("deliver", xid, pid), Task("deliver", yid, qid)))
            yield variant(said, to, "respectively")
        if len(unique) >= 3:
            zid = rng.choice([u for u in unique if u not in (xid, yid)])
            if (said := say(RESPECTIVELY_THREE, z=_name(scene, zid), **keys)) is not None:
                yield variant(said, None, "respectively short")
    if unique:
        if one is not None and one.target is not None and one.obj in unique:
            oid, pid = one.obj, one.target
        else:
            oid, pid = rng.choice(unique), rng.choice(humans)
        o, p = _name(scene, oid), _name(scene, pid)
        them = {"his": "him", "her": "her"}.get(_pronoun_of(p) or "", p)
        if (said := say(OWNER_BACK, o=o, p=p, them=them)) is not None:
            yield variant(said, Task("deliver", oid, pid), "owner")
        others = [h for h in humans if h != pid]
        if others:
            qid = rng.choice(others)
            q = _name(scene, qid)
            if (said := say(OWNER_OTHER, o=o, p=p, q=q)) is not None:
                yield variant(said, Task("deliver", oid, pid), "owner other")
            if (said := say(OWNER_EITHER, o=o, p=p, q=q)) is not None:
                yield variant(said, None, "owner either", (pid, qid))
    reading = [v for v in made if v.must == "same"]
    if reading:
        v = rng.choice(reading)
        yield Variant(part, entry.scene, v.text.lower(), v.want, "same", "said", (), "lower")
        v = rng.choice(reading)
        if (typo := _typo(v.text, scene, rng)) is not None:
            yield Variant(part, entry.scene, typo, v.want, "same", "said", (), "typo")


def holds(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The holds variants of one grounded entry saying no pronoun for a person (HOLDS_FORMS; none
    of a refused one): a remark that a person of the scene (by a name) already holds, still has or
    has had a one-of-a-kind object the entry neither names nor moves, before it (`before`; not
    before an entry that takes back or opens with a joining word) or after it (`after`), or has
    their own one (`own`, either place): the entry, or refused: what a person holds asks for
    nothing (a handover of that object read from it is wrong). Then one of them in lower case
    (`lower`). After a question only the sentence forms follow it."""
    want = entry.want
    text = entry.text.strip()
    if want is None or _words(text) & _PRONOUNS:
        return
    named = _objects_named(text, scene) | {t.obj for t in tasks(want)}
    unnamed = [x for x in _unique_objects(scene) if x not in named]
    names = [n for h in scene.humans if (n := _proper_name(scene, h.id)) is not None]
    if not unnamed or not names:
        return
    question = text.endswith("?")
    takes_back = text.lower().startswith(("scratch that", "no,", "actually", "forget", "sorry"))
    before_ok = not takes_back and not text.lower().startswith(_JOINING39)
    made: list[Variant] = []

    def remark(forms: tuple[str, ...]) -> tuple[str, str] | None:
        """A form of ``forms`` that fits (said before or after as it can be), filled in."""
        fitting = [
            f
            for f in forms
            if _fits(f, scene)
            and (f[:1] in ",;." or before_ok)
            and (f[:1] not in ",;" or not question)
        ]
        if not fitting:
            return None
        form = rng.choice(fitting)
        q = rng.choice(names)
        pos = _pronoun_of(q) or "their"
        return form, form.format(q=q, o=_name(scene, rng.choice(unnamed)), pos=pos)

    for forms, name in ((HOLDS_BEFORE, "before"), (HOLDS_AFTER, "after"), (HOLDS_OWN, "own")):
        if (got := remark(forms)) is None:
            continue
        form, said = got
        said = _then(text, said) if form[:1] in ",;." else _after(said, text, scene)
        v = Variant(part, entry.scene, said, want, "same", "holds", (), name)
        made.append(v)
        yield v
    if made:
        v = rng.choice(made)
        yield Variant(part, entry.scene, v.text.lower(), want, "same", "holds", (), "lower")


_STOPS = re.compile(r"(?:\.\.\.|…|[.,;:!?])+(?=\s|$)")
_APOSTROPHES = re.compile(r"(?<=[A-Za-z])['’](?=[A-Za-z])|(?<=s)['’](?=\s|$)")


def unstopped(text: str) -> str:
    """``text`` without its stops, commas, colons, semicolons, ! and ? (an ellipsis too)."""
    return " ".join(_STOPS.sub("", text).split())


def unapostrophed(text: str) -> str:
    """``text`` without the apostrophes inside or ending its words ("Bob's" -> "Bobs")."""
    return _APOSTROPHES.sub("", text)


def texted(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The texted variants of one grounded entry (TEXTED_FORMS; none of a refused one): the entry
    typed the way people text, without its stops and commas (`stops`), without its apostrophes
    (`apostrophes`), both and in lower case (`texting`; blind43's run-ons: "lilys thirsty after
    her nap so sippy cup to her"), and, for an entry of one handover naming its one person by a
    name that says their sex, texted with a reason of that person run on after it (`run on`: "give
    bob the cup hes been after it all morning"): the entry, or refused (a form is not made where it
    changes nothing)."""
    want = entry.want
    text = entry.text.strip()
    if want is None:
        return
    texting = unstopped(unapostrophed(text)).lower()
    for form, said in (
        ("stops", unstopped(text)),
        ("apostrophes", unapostrophed(text)),
        ("texting", texting),
    ):
        if said != text:
            yield Variant(part, entry.scene, said, want, "same", "texted", (), form)
    one = _one_person_said(text, want, scene)
    name = _proper_name(scene, one[1].target) if one is not None else None
    pronoun = _pronoun_of(name) if name is not None else None
    if pronoun is not None:
        he = "he" if pronoun == "his" else "she"
        said = rng.choice(RUN_ON).format(e=texting, he=he, hes=he + "s")
        yield Variant(part, entry.scene, said, want, "same", "texted", (), "run on")


_HIM = {"his": ("he", "him"), "her": ("she", "her")}


def antecedents(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The antecedent variants of one grounded entry of one handover of a one-of-a-kind object
    naming its one person by a name that says their sex (ANTECEDENT_FORMS; none of another): that
    person said by the name in a remark, a state or a want, then the handover asked for with a
    pronoun for them (`named before`, ANTECEDENTS: that handover); two people of that sex said
    before the pronoun (`two before`, ANTECEDENTS_TWO: refused, both as readings); someone not in
    the scene of that sex said before it instead (`absent before`, ABSENT_HE / ABSENT_SHE in
    ANTECEDENTS: refused); and the first in lower case (`lower`)."""
    one = _one_person_said(entry.text.strip(), entry.want, scene)
    handover = one[1] if one is not None else None
    if handover is None or handover.target is None or handover.obj not in _unique_objects(scene):
        return
    p = _proper_name(scene, handover.target)
    pos = _pronoun_of(p) if p is not None else None
    if p is None or pos is None:
        return
    he, him = _HIM[pos]
    o = _name(scene, handover.obj)
    head = o.split(" of ")[0].split()[-1]
    plural = head.endswith("s") and not head.endswith("ss")
    it, is_, was, that = ("them", "are", "were", "Those") if plural else ("it", "is", "was", "That")
    keys = {"p": p, "P": p, "o": o, "he": he, "him": him, "it": it, "is": is_, "was": was}
    keys["That"] = that
    fitting = [f for f in ANTECEDENTS if _fits(f, scene)]
    if not fitting:
        return
    said = rng.choice(fitting).format(**keys)
    yield Variant(part, entry.scene, said, handover, "same", "antecedents", (), "named before")
    alike = [
        (h.id, q)
        for h in scene.humans
        if h.id != handover.target
        and (q := _proper_name(scene, h.id)) is not None
        and _pronoun_of(q) == pos
    ]
    two = [f for f in ANTECEDENTS_TWO if _fits(f, scene)]
    if alike and two:
        qid, q = rng.choice(alike)
        text = rng.choice(two).format(q=q, **keys)
        readings = (handover.target, qid)
        yield Variant(
            part, entry.scene, text, None, "refuse", "antecedents", readings, "two before"
        )
    absent = [a for a in (ABSENT_HE if pos == "his" else ABSENT_SHE) if _names_nothing(a, scene)]
    if absent:
        a = rng.choice(absent)
        text = rng.choice(fitting).format(**(keys | {"p": a, "P": a[:1].upper() + a[1:]}))
        yield Variant(part, entry.scene, text, None, "refuse", "antecedents", (), "absent before")
    yield Variant(part, entry.scene, said.lower(), handover, "same", "antecedents", (), "lower")


def thoughts(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The thought variants of one grounded entry of one handover of a one-of-a-kind object naming
    its one person by a name (THOUGHT_FORMS; none of another): that handover said as a thought
    and taken back after 'but' for another one-of-a-kind object (`taken back`, THOUGHT_BACK: that
    object to that person) or another person of the scene (`person`, THOUGHT_PERSON: the object
    to them), added to (`added`, THOUGHT_ADDED: both objects to that person) or put after another
    (`first`, THOUGHT_FIRST: the other object, then the entry's); and, after an entry that is no
    question, a hedge with where its object is (`where`, THOUGHT_WHERE: the entry; where a thing
    is asks for nothing) or a hedge alone (`hedge`, THOUGHT_HEDGES: the entry). Each may be
    refused instead."""
    text = entry.text.strip()
    one = _one_person_said(text, entry.want, scene)
    if one is None or one[1].obj not in _unique_objects(scene):
        return
    said, handover = one
    p = _proper_name(scene, handover.target) or said
    o = _name(scene, handover.obj)
    others = [x for x in _unique_objects(scene) if x not in _objects_named(text, scene)]
    others = [x for x in others if x != handover.obj]
    head = o.split(" of ")[0].split()[-1]
    plural = head.endswith("s") and not head.endswith("ss")
    keys = {"p": p, "P": p[:1].upper() + p[1:], "o": o, "it": "them" if plural else "it"}

    def task(obj: str, to: str | None = None) -> Task:
        return Task("deliver", obj, to or handover.target)

    if others:
        xid = rng.choice(others)
        k = keys | {"x": _name(scene, xid)}
        for forms, form, want in (
            (THOUGHT_BACK, "taken back", task(xid)),
            (THOUGHT_ADDED, "added", Group("and", (task(handover.obj), task(xid)))),
            (THOUGHT_FIRST, "first", Group("seq", (task(xid), task(handover.obj)))),
        ):
            fitting = [f for f in forms if _fits(f, scene)]
            if fitting:
                t = rng.choice(fitting).format(**k)
                yield Variant(part, entry.scene, t, want, "same", "thoughts", (), form)
    people = [
        (h.id, q)
        for h in scene.humans
        if h.id != handover.target and (q := _proper_name(scene, h.id)) is not None
    ]
    fitting = [f for f in THOUGHT_PERSON if _fits(f, scene)]
    if people and fitting:
        qid, q = rng.choice(people)
        t = rng.choice(fitting).format(q=q, **keys)
        yield Variant(
            part, entry.scene, t, task(handover.obj, qid), "same", "thoughts", (), "person"
        )
    if text.endswith("?"):
        return
    its = "they're" if plural else "it's"
    surfaces = [n for s in scene.surfaces if (n := _surface_name(scene, s.id)) is not None]
    fitting = [f for f in THOUGHT_WHERE if _fits(f, scene)]
    if surfaces and fitting:
        where = rng.choice(fitting).format(its=its, s=rng.choice(surfaces))
        yield Variant(
            part, entry.scene, _then(text, where), handover, "same", "thoughts", (), "where"
        )
    hedge = rng.choice(THOUGHT_HEDGES)
    yield Variant(part, entry.scene, _then(text, hedge), handover, "same", "thoughts", (), "hedge")


def chains(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The chain variants of one grounded entry that is no question (CHAIN_FORMS; none of
    another): a first correction and a second after it. After an entry of one handover of a
    one-of-a-kind object naming its one person by a name and nothing else of the scene: the person
    then the object (`person, object`, CHAIN_PERSON_OBJECT), the object then the person (`object,
    person`, CHAIN_OBJECT_PERSON): the other object to the other person; the object twice
    (`objects`, CHAIN_OBJECTS: the last object to the person), the person twice (`people`,
    CHAIN_PEOPLE: the object to the last person), corrected and put back (`back`, CHAIN_BACK: the
    entry), a hesitation between people (`hesitation`, CHAIN_HESITATIONS: the object to the one it
    settles on), the person corrected then a placing instead (`placed`, CHAIN_PLACED: the object
    on that surface); a second object added and then one of the two corrected (`which`,
    CHAIN_WHICH: refused, both as readings). After an entry of one placing of a one-of-a-kind
    object naming no person and nothing else of the scene: the surface then a handover instead
    (`surface, person`), the surface corrected and put back (`surface back`: the entry), the
    surface then the object (`surface, object`: the other object on the other surface). Each may
    be refused instead."""
    text = entry.text.strip()
    want = entry.want
    if text.endswith("?") or not isinstance(want, Task) or want.obj not in _unique_objects(scene):
        return
    others = [x for x in _unique_objects(scene) if x not in _objects_named(text, scene)]
    others = [x for x in others if x != want.obj]
    rng.shuffle(others)
    o = _name(scene, want.obj)

    def one(forms: tuple[str, ...], **keys: str) -> str | None:
        fitting = [f for f in forms if _fits(f, scene)]
        return _then(text, rng.choice(fitting).format(o=o, **keys)) if fitting else None

    def variant(
        said: str | None, to: Node | None, form: str, readings: tuple[str, ...] = ()
    ) -> Iterator[Variant]:
        if said is not None:
            yield Variant(
                part, entry.scene, said, to, "same" if to else "refuse", "chains", readings, form
            )

    if want.kind == "place":
        if _people_said(text, scene) or _named(text, scene, "surface") != {want.target}:
            return
        s = _surface_name(scene, want.target)
        surfaces = [
            (sid, t)
            for x in scene.surfaces
            if x.id != want.target and (t := _surface_name(scene, (sid := x.id))) is not None
        ]
        people = [(h.id, q) for h in scene.humans if (q := _proper_name(scene, h.id))]
        if s is None or not surfaces:
            return
        tid, t = rng.choice(surfaces)
        if people:
            qid, q = rng.choice(people)
            said = one(CHAIN_SURFACE_PERSON, t=t, q=q)
            yield from variant(said, Task("deliver", want.obj, qid), "surface, person")
        yield from variant(one(CHAIN_SURFACE_BACK, s=s, t=t), want, "surface back")
        if others:
            said = one(CHAIN_SURFACE_OBJECT, t=t, x=_name(scene, others[0]))
            yield from variant(said, Task("place", others[0], tid), "surface, object")
        return
    said_as = _one_person_said(text, want, scene)
    if said_as is None:
        return
    p = _proper_name(scene, want.target) or said_as[0]
    people = [
        (h.id, q)
        for h in scene.humans
        if h.id != want.target and (q := _proper_name(scene, h.id)) is not None
    ]
    rng.shuffle(people)
    if people and others:
        (qid, q), x = people[0], _name(scene, others[0])
        said = one(CHAIN_PERSON_OBJECT, q=q, x=x)
        yield from variant(said, Task("deliver", others[0], qid), "person, object")
        said = one(CHAIN_OBJECT_PERSON, q=q, x=x, p=p)
        yield from variant(said, Task("deliver", others[0], qid), "object, person")
    if len(others) >= 2:
        said = one(CHAIN_OBJECTS, x=_name(scene, others[0]), y=_name(scene, others[1]))
        yield from variant(said, Task("deliver", others[1], want.target), "objects")
    if len(people) >= 2:
        (_, q), (rid, r) = people[:2]
        yield from variant(one(CHAIN_PEOPLE, q=q, r=r), Task("deliver", want.obj, rid), "people")
    if people and others:
        said = one(CHAIN_BACK, x=_name(scene, others[0]), q=people[0][1], p=p)
        yield from variant(said, want, "back")
    if people:
        ids = {"p": want.target, "q": people[0][0], "r": people[-1][0]}
        forms = [(f, k) for f, k in CHAIN_HESITATIONS if _fits(f, scene)]
        forms = [(f, k) for f, k in forms if len(people) >= 2 or "{r}" not in f]
        if forms:
            f, k = rng.choice(forms)
            said = _then(text, f.format(p=p, q=people[0][1], r=people[-1][1]))
            yield from variant(said, Task("deliver", want.obj, ids[k]), "hesitation")
    if people and len(others) >= 2:
        x, y = (_name(scene, i) for i in others[:2])
        said = one(CHAIN_WHICH, x=x, q=people[0][1], y=y)
        yield from variant(said, None, "which", (want.obj, others[0]))
    surfaces = [(x.id, n) for x in scene.surfaces if (n := _surface_name(scene, x.id))]
    if people and surfaces:
        sid, s = rng.choice(surfaces)
        said = one(CHAIN_PLACED, q=people[0][1], s=s)
        yield from variant(said, Task("place", want.obj, sid), "placed")


def forgets(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The forgetting variants of one grounded entry that is no question (FORGET_FORMS; none of
    another): with a choice in its reading, a remark after it that the speaker has forgotten or
    never knew which (`closed`, FORGET_CLOSERS: refused); of one handover of a one-of-a-kind
    object naming its one person by a name and nothing else of the scene, that object or another
    said as the person's want and closed by such a remark (`objects`, FORGET_OBJECTS: refused,
    both as readings), or that person or another (`people`, FORGET_PEOPLE: refused); that object
    or another asked for, then which it was said (`named`, FORGET_NAMED: the entry)."""
    text = entry.text.strip()
    want = entry.want
    if text.endswith("?") or want is None:
        return
    closers = [c for c in FORGET_CLOSERS if _names_nothing(c, scene)]
    if not closers:
        return
    closer = rng.choice(closers)
    if has_choice(want) and not _words(text) & _FREE_CHOICE:
        yield Variant(
            part, entry.scene, _then(text, closer), None, "refuse", "forgets", (), "closed"
        )
    if has_choice(want):
        free = _then(text, rng.choice(FORGET_FREE))
        yield Variant(part, entry.scene, free, want, "same", "forgets", (), "free")
    said_as = _one_person_said(text, want, scene)
    if said_as is None or not isinstance(want, Task) or want.obj not in _unique_objects(scene):
        return
    p = _proper_name(scene, want.target or "") or said_as[0]
    keys = {"p": p, "P": p[:1].upper() + p[1:], "o": _name(scene, want.obj), "c": closer}
    others = [x for x in _unique_objects(scene) if x != want.obj]
    fitting = [f for f in FORGET_OBJECTS if _fits(f, scene)]
    if others and fitting:
        xid = rng.choice(others)
        said = rng.choice(fitting).format(x=_name(scene, xid), **keys)
        readings = (want.obj, xid)
        yield Variant(part, entry.scene, said, None, "refuse", "forgets", readings, "objects")
    people = [q for h in scene.humans if h.id != want.target and (q := _proper_name(scene, h.id))]
    fitting = [f for f in FORGET_PEOPLE if _fits(f, scene)]
    if people and fitting:
        said = rng.choice(fitting).format(q=rng.choice(people), **keys)
        yield Variant(part, entry.scene, said, None, "refuse", "forgets", (), "people")
    fitting = [f for f in FORGET_NAMED if _fits(f, scene)]
    if others and fitting:
        said = rng.choice(fitting).format(x=_name(scene, rng.choice(others)), **keys)
        yield Variant(part, entry.scene, said, want, "same", "forgets", (), "named")


def kin(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The kin variants of one grounded entry that is no question, of one task of a one-of-a-kind
    object, in a scene with a person named by a word of kin or a title (KIN_NAMED; KIN_FORMS; none
    of another): that person said to say a pronoun of the other sex wants the object (`wants`,
    KIN_WANTS) or asked for it and it is to go to such a pronoun (`given`, KIN_GIVEN): refused;
    a pronoun of their own sex wants it, where no one else of the scene is of that sex (`same`,
    KIN_WANTS): the object to that person."""
    text = entry.text.strip()
    want = entry.want
    if text.endswith("?") or not isinstance(want, Task) or want.obj not in _unique_objects(scene):
        return
    said = {h.id: n for h in scene.humans if (n := _proper_name(scene, h.id)) in KIN_NAMED}
    if not said:
        return
    hid = rng.choice(sorted(said))
    k = said[hid]
    he = k in NAMED_HE
    keys = {"K": k, "o": _name(scene, want.obj)}
    other = {"s": "she", "h": "her"} if he else {"s": "he", "h": "him"}
    fitting = [f for f in KIN_WANTS if _fits(f, scene)]
    if fitting:
        said_as = rng.choice(fitting).format(**keys, **other)
        yield Variant(part, entry.scene, said_as, None, "refuse", "kin", (), "wants")
    fitting_given = [f for f in KIN_GIVEN if _fits(f, scene)]
    if fitting_given:
        said_as = rng.choice(fitting_given).format(**keys, **other)
        yield Variant(part, entry.scene, said_as, None, "refuse", "kin", (), "given")
    alone = all(
        _proper_name(scene, h.id) in (NAMED_SHE if he else NAMED_HE)
        for h in scene.humans
        if h.id != hid
    )
    if fitting and alone:
        same = {"s": "he", "h": "him"} if he else {"s": "she", "h": "her"}
        said_as = rng.choice(fitting).format(**keys, **same)
        got = Task("deliver", want.obj, hid)
        yield Variant(part, entry.scene, said_as, got, "same", "kin", (), "same")


def lots(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The 'whole lot' variants of one grounded entry of one handover naming its one person by a
    name and nothing else of the scene but its object (LOT_FORMS; none of another): in a scene
    with a kind it has several objects of, that kind's plural for the person with 'the whole lot'
    in apposition (`kind`, LOT_KIND: every one of the kind to them) or on a surface of the scene
    (`placed`, LOT_PLACED: every one on it); and, for the entry's one-of-a-kind object, it and
    another one named for the person with 'the whole lot' after them (`named`, LOT_NAMED: those
    again or everything else: refused, both objects as readings)."""
    text = entry.text.strip()
    want = entry.want
    said_as = _one_person_said(text, want, scene)
    if text.endswith("?") or said_as is None or not isinstance(want, Task):
        return
    p = _proper_name(scene, want.target or "") or said_as[0]
    plurals = _plurals(scene)
    if plurals:
        cs, (_, ids) = rng.choice(sorted(plurals.items()))
        every = Group("and", tuple(Task("deliver", i, want.target) for i in ids))
        fitting = [f for f in LOT_KIND if _fits(f, scene)]
        if fitting:
            said = rng.choice(fitting).format(p=p, cs=cs)
            yield Variant(part, entry.scene, said, every, "same", "lots", (), "kind")
        surfaces = [(x.id, n) for x in scene.surfaces if (n := _surface_name(scene, x.id))]
        fitting = [f for f in LOT_PLACED if _fits(f, scene)]
        if surfaces and fitting:
            sid, s = rng.choice(surfaces)
            placed = Group("and", tuple(Task("place", i, sid) for i in ids))
            said = rng.choice(fitting).format(s=s, cs=cs)
            yield Variant(part, entry.scene, said, placed, "same", "lots", (), "placed")
    others = [x for x in _unique_objects(scene) if x != want.obj]
    fitting = [f for f in LOT_NAMED if _fits(f, scene)]
    # (where the two are everything in the scene, the two readings are one)
    if want.obj in _unique_objects(scene) and len(scene.objects) > 2 and others and fitting:
        xid = rng.choice(others)
        said = rng.choice(fitting).format(p=p, o=_name(scene, want.obj), x=_name(scene, xid))
        readings = (want.obj, xid)
        yield Variant(part, entry.scene, said, None, "refuse", "lots", readings, "named")


def done(part: str, entry: Entry, scene: Scene, rng: random.Random) -> Iterator[Variant]:
    """The done variants of one grounded entry that is no question, of one handover of a
    one-of-a-kind object naming its one person by a name and nothing else of the scene (DONE_FORMS;
    none of another): that handover said as already done or as no request (`said`, DONE_SAID) or
    the entry followed by a remark that it is seen to (`after`, DONE_AFTER): refused; ticked off
    before another one-of-a-kind object for the person (`checklist`, DONE_CHECKLIST) or a want of it
    replaced by a want of another (`replaced`, DONE_REPLACED): the handover of the other only."""
    text = entry.text.strip()
    want = entry.want
    said_as = _one_person_said(text, want, scene)
    if text.endswith("?") or said_as is None or not isinstance(want, Task):
        return
    if want.obj not in _unique_objects(scene) or want.target is None:
        return
    p = _proper_name(scene, want.target) or said_as[0]
    o = _name(scene, want.obj)
    people = [q for h in scene.humans if h.id != want.target and (q := _proper_name(scene, h.id))]
    q = rng.choice(people) if people else None
    keys = {"p": p, "P": p[:1].upper() + p[1:], "o": o, "O": o[:1].upper() + o[1:]}
    if q is not None:
        keys |= {"q": q, "Q": q[:1].upper() + q[1:]}
    fitting = [f for f in DONE_SAID if _fits(f, scene) and (q is not None or "{q" not in f.lower())]
    if fitting:
        said = rng.choice(fitting).format(**keys)
        yield Variant(part, entry.scene, said, None, "refuse", "done", (), "said")
    after = [c for c in DONE_AFTER if _names_nothing(c, scene)]
    if after:
        said = _then(text, rng.choice(after))
        yield Variant(part, entry.scene, said, None, "refuse", "done", (), "after")
    others = [x for x in _unique_objects(scene) if x != want.obj]
    if not others:
        return
    xid = rng.choice(others)
    other = Task("deliver", xid, want.target)
    for form, forms in (("checklist", DONE_CHECKLIST), ("replaced", DONE_REPLACED)):
        fitting = [f for f in forms if _fits(f, scene)]
        if fitting:
            said = rng.choice(fitting).format(x=_name(scene, xid), **keys)
            yield Variant(part, entry.scene, said, other, "same", "done", (), form)


def _one_id(name: str, scene: Scene) -> str:
    (hid,) = _named(name, scene, "human")
    return hid


def _dropped(node: Node, task: Task) -> Node | None:
    """``node`` without ``task`` (the order and choices among the rest kept), or None if empty."""
    if isinstance(node, Task):
        return None if node == task else node
    kids = [k for k in (_dropped(c, task) for c in node.children) if k is not None]
    if not kids:
        return None
    return kids[0] if len(kids) == 1 else Group(node.op, tuple(kids))


def _in_choice(node: Node, task: Task) -> bool:
    if isinstance(node, Task):
        return False
    if node.op == "or" and any(t == task for t in tasks(node)):
        return True
    return any(_in_choice(c, task) for c in node.children)


def kept(got: Node, want: Node, added: Task) -> bool:
    """A tail that adds ``added``: read once and not as an option, and the rest read as the
    entry (``want`` without ``added``), neither loosened nor dropped. Where the added handover
    falls in an order of the entry is not judged: "X last. Also, give Bob the chips." may put
    the chips before X."""
    if sum(1 for t in tasks(got) if t == added) != 1 or _in_choice(got, added):
        return False
    rest, entry = _dropped(got, added), _dropped(want, added)
    if rest is None or entry is None:
        return rest is entry
    if show_tree(rest) == show_tree(entry):
        return True
    return counterexample(spec_of(rest), spec_of(entry)) is None


def verdict(variant: Variant, scene: Scene) -> Literal["exact", "refused", "unclear", "wrong"]:
    """How the grounder reads a variant: as it must, refused (without a reading it must name:
    unclear), or otherwise (wrong)."""
    try:
        got = parse_instruction(variant.text, scene)
    except GroundingError as exc:
        return "unclear" if any(r not in str(exc) for r in variant.readings) else "refused"
    if variant.must == "refuse" or variant.want is None:
        return "wrong"
    if variant.added is not None:
        return "exact" if kept(got, variant.want, variant.added) else "wrong"
    if show_tree(got) == show_tree(variant.want):
        return "exact"
    same = counterexample(spec_of(got), spec_of(variant.want)) is None
    return "exact" if same else "wrong"


def generated(
    parts: tuple[str, ...] = PARTS,
    seed: int = 16,
    every: int = 1,
    families: tuple[Family, ...] = FAMILIES,
) -> Iterator[tuple[Variant, Scene]]:
    """The variants of every ``every``-th entry of ``parts`` in ``families`` with ``seed``, each
    with its scene. Each family draws from its own generator, so a seed gives the wrappers of
    earlier sessions whatever else runs."""
    rng = random.Random(seed)
    rng_back = random.Random(f"takebacks:{seed}")
    rng_refs = random.Random(f"references:{seed}")
    rng_excl = random.Random(f"exclusions:{seed}")
    rng_tail = random.Random(f"tails:{seed}")
    rng_aside = random.Random(f"asides:{seed}")
    rng_after = random.Random(f"afterthoughts:{seed}")
    rng_frames = random.Random(f"frames:{seed}")
    rng_repairs = random.Random(f"repairs:{seed}")
    rng_defer = random.Random(f"deferrals:{seed}")
    rng_clefts = random.Random(f"clefts:{seed}")
    rng_counts = random.Random(f"counts:{seed}")
    rng_remarks = random.Random(f"remarks:{seed}")
    rng_remarks39 = random.Random(f"remarks39:{seed}")
    rng_purposes = random.Random(f"purposes:{seed}")
    rng_idioms = random.Random(f"idioms:{seed}")
    rng_turns = random.Random(f"turns:{seed}")
    rng_said = random.Random(f"said:{seed}")
    rng_holds = random.Random(f"holds:{seed}")
    rng_texted = random.Random(f"texted:{seed}")
    rng_antecedents = random.Random(f"antecedents:{seed}")
    rng_thoughts = random.Random(f"thoughts:{seed}")
    rng_chains = random.Random(f"chains:{seed}")
    rng_forgets = random.Random(f"forgets:{seed}")
    rng_lots = random.Random(f"lots:{seed}")
    rng_kin = random.Random(f"kin:{seed}")
    rng_done = random.Random(f"done:{seed}")
    for part in parts:
        corpus = load_corpus(ROOT / CORPUS_DIR / f"{part}.yaml", ROOT)
        for n, entry in enumerate(corpus.entries):
            if n % every:
                continue
            scene = corpus.scenes[entry.scene]
            if "wrappers" in families:
                for v in variants(part, entry, scene, rng):
                    yield v, scene
            if "takebacks" in families:
                for v in takebacks(part, entry, scene, rng_back):
                    yield v, scene
            if "references" in families:
                for v in references(part, entry, scene, rng_refs):
                    yield v, scene
            if "exclusions" in families:
                for v in exclusions(part, entry, scene, rng_excl):
                    yield v, scene
            if "tails" in families:
                for v in tails(part, entry, scene, rng_tail):
                    yield v, scene
            if "asides" in families:
                for v in asides(part, entry, scene, rng_aside):
                    yield v, scene
            if "afterthoughts" in families:
                for v in afterthoughts(part, entry, scene, rng_after):
                    yield v, scene
            if "frames" in families:
                for v in frames(part, entry, scene, rng_frames):
                    yield v, scene
            if "repairs" in families:
                for v in repairs(part, entry, scene, rng_repairs):
                    yield v, scene
            if "deferrals" in families:
                for v in deferrals(part, entry, scene, rng_defer):
                    yield v, scene
            if "clefts" in families:
                for v in clefts(part, entry, scene, rng_clefts):
                    yield v, scene
            if "counts" in families:
                for v in counts(part, entry, scene, rng_counts):
                    yield v, scene
            if "remarks" in families:
                for v in remarks(part, entry, scene, rng_remarks):
                    yield v, scene
                for v in remarks39(part, entry, scene, rng_remarks39):
                    yield v, scene
            if "purposes" in families:
                for v in purposes(part, entry, scene, rng_purposes):
                    yield v, scene
            if "idioms" in families:
                for v in idioms(part, entry, scene, rng_idioms):
                    yield v, scene
            if "turns" in families:
                for v in turns(part, entry, scene, rng_turns):
                    yield v, scene
            if "said" in families:
                for v in said_around(part, entry, scene, rng_said):
                    yield v, scene
            if "holds" in families:
                for v in holds(part, entry, scene, rng_holds):
                    yield v, scene
            if "texted" in families:
                for v in texted(part, entry, scene, rng_texted):
                    yield v, scene
            if "antecedents" in families:
                for v in antecedents(part, entry, scene, rng_antecedents):
                    yield v, scene
            if "thoughts" in families:
                for v in thoughts(part, entry, scene, rng_thoughts):
                    yield v, scene
            if "chains" in families:
                for v in chains(part, entry, scene, rng_chains):
                    yield v, scene
            if "forgets" in families:
                for v in forgets(part, entry, scene, rng_forgets):
                    yield v, scene
            if "lots" in families:
                for v in lots(part, entry, scene, rng_lots):
                    yield v, scene
            if "kin" in families:
                for v in kin(part, entry, scene, rng_kin):
                    yield v, scene
            if "done" in families:
                for v in done(part, entry, scene, rng_done):
                    yield v, scene


def run(
    parts: tuple[str, ...] = PARTS,
    seed: int = 16,
    every: int = 1,
    families: tuple[Family, ...] = FAMILIES,
) -> tuple[Counter[str], list[tuple[Variant, str]]]:
    """Every ``every``-th entry of ``parts`` fuzzed with ``seed`` in ``families``: the counts by
    verdict and the wrong readings (each with what was read)."""
    counts: Counter[str] = Counter()
    wrong: list[tuple[Variant, str]] = []
    for v, scene in generated(parts, seed, every, families):
        result = verdict(v, scene)
        counts[
            f"{v.must}:{result}" if v.family == "wrappers" else f"{v.family}:{v.must}:{result}"
        ] += 1
        if result == "wrong":
            wrong.append((v, show_tree(parse_instruction(v.text, scene))))
    return counts, wrong


def main(argv: list[str] | None = None) -> int:
    from tests.grounding.test_paraphrase import MEASURED_ONLY  # the held-back part: not fuzzed

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=16)
    parser.add_argument("--parts", default=",".join(p for p in PARTS if p not in MEASURED_ONLY))
    parser.add_argument("--every", type=int, default=1, help="fuzz every n-th entry only")
    parser.add_argument(
        "--families", default=",".join(FAMILIES), help=f"some of {', '.join(FAMILIES)}"
    )
    args = parser.parse_args(argv)
    parts = tuple(p for p in args.parts.split(",") if p)
    families: list[Family] = []
    for name in (f for f in args.families.split(",") if f):
        if name not in FAMILIES:
            parser.error(f"--families: no family called {name!r}, expected some of {FAMILIES}")
        families.append(cast(Family, name))
    counts, wrong = run(parts, args.seed, args.every, tuple(families))
    for key in sorted(counts):
        print(f"{key}: {counts[key]}")
    print(f"variants: {sum(counts.values())}, wrong: {len(wrong)}")
    for v, read in wrong:
        want = show_tree(v.want) if v.want is not None else "a refusal"
        print(f"WRONG [{v.part}] {v.scene}: {v.text!r} read {read}, want {want}")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
