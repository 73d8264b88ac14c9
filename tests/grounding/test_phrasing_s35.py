"""Session-35 phrasings of issue 12 (engineer 12): blind33's refusals by kind in its sections of
politeness, wants, pronouns and ellipsis, sentence splits, lower case, typos and questions, the
clefts fuzz family's, and the same kinds in blind16 and blind13 (docs/grounding.md, "Session 35
(engineer 12)"). Each rule with sentences it reads (which fail with the rule taken out) and near
sentences that must stay refused."""

from __future__ import annotations

import pytest

from tests.grounding.helpers import (
    CELL,
    DEPOT,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

READS = [
    # (a) 'and after it' before the next object: after that
    ("Give Bob the apple and after it the cup.", "apple>B ; cup>B", CELL),
    ("the cup for bob and after it the apple for carol", "cup>B ; apple>C", CELL),
    # (b) a negated want idiom (a closed list) with the subject's own pronoun
    ("Mrs Khan won't sleep without her magazine.", "magazine>C", WARD),
    ("Carol won't settle without her apple.", "apple>C", CELL),
    ("Bob won't sleep without his crisps, so give them to him.", "chips>B", CELL),
    # (c) what made the person want it: a pastime, closing
    ("Carol wants the cup after her crochet.", "cup>C", CELL),
    ("Bob could do with the apple after a day's fishing.", "apple>B", CELL),
    (
        "Alice wants the cup and Bob could do with the apple after his darts.",
        "cup>A & apple>B",
        CELL,
    ),
    # (d) the want said of the object at the person's end, and once they're there: after that
    ("Crisps are needed over at Carol's end.", "chips>C", CELL),
    ("The apple is wanted at Bob's desk.", "apple>B", CELL),
    (
        "Crisps are needed over at Carol's end, and once they're there, Bob wants the apple.",
        "chips>C ; apple>B",
        CELL,
    ),
    # (f) the hearer asked to see to it, closing
    ("Bob fancies the apple, if you'd sort that.", "apple>B", CELL),
    ("The cup on the shelf, if you could see to it.", "cup@shelf", CELL),
    ("Bob fancies the apple, if you'd sort that out for me.", "apple>B", CELL),
    # (g) how the object is to stand where the speaker wants it
    ("I'd like the cup sat on the shelf.", "cup@shelf", CELL),
    (
        "Bob wants the apple, and we'd like the red mug sitting on the table.",
        "apple>B & mug_red@table",
        CELL,
    ),
    # (h) where the object is bound
    ("The cup's headed for Carol.", "cup>C", CELL),
    ("The apple is bound for Bob, and the cup for Carol.", "apple>B & cup>C", CELL),
    # (i) clefts: the person first, asking after or what is for them; (j) the place first
    ("It was Carol who asked after the cup.", "cup>C", CELL),
    ("It's Bob that's after the crisps, so take them to him.", "chips>B", CELL),
    ("It's Bob that the apple is for.", "apple>B", CELL),
    ("It was Carol that the crisps were meant for.", "chips>C", CELL),
    ("The shelf is where the cup goes.", "cup@shelf", CELL),
    ("The table is where the crisps belong.", "chips@table", CELL),
    # (k) a second object to go along with the first
    ("The gloves go to Tom, and the scanner can go with them.", "gloves>B & scanner>B", DEPOT),
    (
        "The apple goes on the shelf, and the cup can go along with it.",
        "apple@shelf & cup@shelf",
        CELL,
    ),
    # (l) a state of the object (where it lies), then the request of 'it'
    ("The teddy's fallen on the floor, put it on the play mat.", "teddy@mat", NURSERY),
    ("The red mug's in the way, pop it on the shelf.", "mug_red@shelf", CELL),
    ("The cup has fallen over, so give it to Bob.", "cup>B", CELL),
    # (m) the placement with the place first and the object after 'with'
    ("Apple to Bob. Then up on the shelf with the red mug.", "apple>B ; mug_red@shelf", CELL),
    ("Apple to Bob, then onto the table with the cup.", "apple>B ; cup@table", CELL),
    # (n) telegraph: the object and its recipient as sentences of their own
    ("The cup. For Carol. She drives the night bus. Ta.", "cup>C", CELL),
    ("The apple. For Bob. He works the late shift.", "apple>B", CELL),
    # (o) what someone of a trade does after the tasks
    ("Small box onto the pallet, and then the foreman can lock up.", "box_small@pallet", DEPOT),
    ("The scanner to Tom and then the cleaner can go home.", "scanner>B", DEPOT),
    # (p) where the person just named is, at a surface of the scene
    (
        "Torch to Jess, she's under the bench, then the hammer to Kofi.",
        "torch>B ; hammer>A",
        WORKSHOP,
    ),
    # (q) a want run on into the request to carry it out
    ("the cup's meant for bob so take it over", "cup>B", CELL),
    ("bob is after his crisps can you get them to him", "chips>B", CELL),
    # (r) the person's care (a closed list), closing
    ("Bib to Ava, Lily needs feeding.", "bib>C", NURSERY),
    ("Wipes to Grandad, the baby needs changing.", "wipes>B", NURSERY),
    # (s) what the person will be doing when she has them
    ("Carol's having the apple with her tea.", "apple>C", CELL),
    ("Bob is having the crisps and the cup with his lunch.", "chips>B & cup>B", CELL),
    # (t) the order said with openers and followers of a closed list
    (
        "Kick off with the cup for Bob, and follow up with the apple for Carol.",
        "cup>B ; apple>C",
        CELL,
    ),
    (
        "Lead off with the crisps to Alice and finish off with the cup to Bob.",
        "chips>A ; cup>B",
        CELL,
    ),
    # (u) the place asked about, then the placement of 'it' there
    ("Would the table be a better home for the cup? Put it there.", "cup@table", CELL),
    (
        "Would the shelf be a better home for the crisps? Pop them up there, ta.",
        "chips@shelf",
        CELL,
    ),
    # (v) leave to send her off with it; ', what do you say?' after 'how about'
    ("Bob's off out; is it alright to send him off with the apple?", "apple>B", CELL),
    ("Is it okay to send Carol off with the cup and the crisps?", "cup>C & chips>C", CELL),
    ("How about giving Bob the cup, what do you say?", "cup>B", CELL),
    # (w) who the person is, then the request by pronoun; what she is having; can P take X?
    ("Emma's just a visitor, but can she have the spoon?", "spoon>C", LAB),
    ("Omar's just a technician, but can he have the bowl?", "bowl>B", LAB),
    ("Put the stapler in the box, Sam's having a break.", "stapler@box", OFFICE),
    ("Can Jess take the hammer and the screws?", "hammer>B & screws>B", WORKSHOP),
    ("Could Kofi take the drill?", "drill>A", WORKSHOP),
    # (x) the hearer told to get the wants sorted, a rest offered after it (blind16)
    (
        "Bob is waiting on the cup and Carol on the apple so get those sorted and then you can "
        "have a rest",
        "cup>B & apple>C",
        CELL,
    ),
    ("Bob wants the cup and Carol the apple, so get those sorted.", "cup>B & apple>C", CELL),
    # (y) office speech: 'action' before the doing (blind16)
    ("can we action getting the stapler over to Priya?", "stapler>A", OFFICE),
    ("can you action putting the stapler in the box?", "stapler@box", OFFICE),
    # (z) what the person has not had, then the handover of it (blind13)
    (
        "Mr Lee hasn't had his pills, take them over, then the magazine.",
        "pills>B ; magazine>B",
        WARD,
    ),
]


@pytest.mark.parametrize(("text", "want", "scene"), READS)
def test_blind33_kinds_read(text: str, want: str, scene: object) -> None:
    assert_reads(text, want, scene)  # type: ignore[arg-type]


REFUSED = [
    # (a) 'after it' before a person: no object follows
    ("Give Bob the apple and after it Carol.", CELL),
    # (b) a pronoun against the title; a surface or a person to be without
    ("Mrs Khan won't sleep without his magazine.", WARD),
    ("Carol won't settle without the shelf.", CELL),
    ("Carol won't settle without Bob.", CELL),
    # (c) a pronoun against the title; a time, or an event (when, not why), is no pastime
    ("Mrs Khan wants the magazine after his darts.", WARD),
    ("Carol wants the cup after her morning.", CELL),
    ("Carol wants the cup after the meeting.", CELL),
    ("Carol wants the cup after the wedding.", CELL),
    # (d) a surface wanted; a surface's end; a place not of the closed list
    ("The shelf is needed over at Carol's end.", CELL),
    ("Crisps are needed over at the shelf's end.", CELL),
    ("Crisps are needed over at Carol's house.", CELL),
    # (e) 'once it's there' after no place of a person's end (session 11's: 'there' is a surface)
    ("Give Bob the cup, and once it's there, Carol wants the apple.", CELL),
    ("Bob wants the cup, and once it's there, Carol wants the apple.", CELL),
    # (f) a condition of the world; something else to sort; nothing to see to
    ("Bob fancies the apple, if it's clean.", CELL),
    ("Bob fancies the apple, if you'd sort the cup.", CELL),
    ("The apple, if you'd sort that.", CELL),
    # (g) sat on a person, by a person; a person sat
    ("I'd like the cup sat on Bob.", CELL),
    ("I'd like the cup sat on the shelf by Bob.", CELL),
    ("I'd like Bob sat on the shelf.", CELL),
    ("I'd like the cup left on the shelf.", CELL),
    # (h) headed for two people; a person headed somewhere
    ("The cup's headed for Carol and Bob.", CELL),
    ("Bob's headed for Carol.", CELL),
    # (i) after a person; a surface for a person; the apple for a surface; a negation
    ("It was Carol who asked after Bob.", CELL),
    ("It's Bob that the shelf is for.", CELL),
    ("It's the shelf that the apple is for.", CELL),
    ("It's Bob that the apple isn't for.", CELL),
    # (j) a person where the cup goes; a person going; where it went (no request)
    ("Bob is where the cup goes.", CELL),
    ("The shelf is where Bob goes.", CELL),
    ("The shelf is where the cup went.", CELL),
    # (k) 'them' for one object; two recipients before; a person going along; another sentence
    ("The apple goes on the shelf, and the cup can go along with them.", CELL),
    ("The apple goes to Bob and Carol, and the cup can go along with it.", CELL),
    ("The apple goes on the shelf, and Bob can go along with it.", CELL),
    ("The apple goes on the shelf. The cup can go along with it.", CELL),
    # (l) the pronoun against the number; a person in the way; in the way of a scene thing
    ("The red mug's in the way, pop them on the shelf.", CELL),
    ("Bob's in the way, put it on the shelf.", CELL),
    ("The red mug's in the way of the cup, put it on the shelf.", CELL),
    # (m) a person after 'with'; an object already placed before it
    ("Up on the shelf with Bob.", CELL),
    ("Put the apple on the shelf with the cup.", CELL),
    # (n) for a surface; two people; a person first
    ("The cup. For the shelf.", CELL),
    ("The cup. For Carol and Bob.", CELL),
    ("Carol. For the cup.", CELL),
    # (o) a person of the scene goes home; someone of a trade gets something
    ("The scanner to Tom and then Mia can go home.", DEPOT),
    ("The scanner to Tom and then the foreman can have the gloves.", DEPOT),
    # (p) a pronoun against the title
    ("Jug to Mrs Khan, he's by the trolley.", WARD),
    # (q) another object in the request; a surface the object is for
    ("bob is after his crisps can you get the apple to him", CELL),
    ("the cup's meant for bob so take the apple over", CELL),
    ("the cup's meant for the shelf so take it over", CELL),
    # (r) the care alone; as a sentence of its own
    ("Lily needs changing.", NURSERY),
    ("Wipes to Grandad. Lily needs changing.", NURSERY),
    # (s) a pronoun against the title; with an object or a person of the scene
    ("Mrs Khan is having the jug with his lunch.", WARD),
    ("Carol's having the apple with the cup.", CELL),
    ("Carol's having the apple with Bob's lunch.", CELL),
    # (t) the follower a surface; an opener without a person; a person as the opener's object
    ("Kick off with the cup for Bob, and follow up with the shelf.", CELL),
    ("Kick off with the cup, and follow up with the apple for Carol.", CELL),
    ("Kick off with Bob for the cup, and follow up with the apple for Carol.", CELL),
    # (u) 'them' for one object; a person as the home; no placement after; another place
    ("Would the shelf be a better home for the cup? Pop them up there.", CELL),
    ("Would Bob be a better home for the cup? Put it there.", CELL),
    ("Would the shelf be a better home for the cup?", CELL),
    # (v) two people before 'her'; off with a person or a surface; no 'how about' before
    ("Bob and Carol are off out; is it alright to send her off with the apple?", CELL),
    ("Is it okay to send Carol off with Bob?", CELL),
    ("Is it okay to send Carol off with the shelf?", CELL),
    ("Give Bob the cup, what do you say?", CELL),
    # (w) a pronoun against the title; a person or a surface to have; a surface as the role;
    # something of the scene's kind to have; the remark alone; take to a person or surface
    ("Mrs Khan's just a patient, but can he have the jug?", WARD),
    ("Carol's just a visitor, but can she have Bob?", CELL),
    ("Carol's just a shelf, but can she have the cup?", CELL),
    ("Put the stapler in the box, Sam's having a biscuit.", OFFICE),
    ("Sam's having a tidy-up.", OFFICE),
    ("Can Jess take the hammer to Kofi?", WORKSHOP),
    ("Can Jess take the hammer to the bench?", WORKSHOP),
    ("Can Jess take Kofi?", WORKSHOP),
    ("Can Jess take the bench?", WORKSHOP),
    # (x) the pronoun against the number; before a sentence mark
    ("Bob wants the cup, so get them sorted.", CELL),
    ("Bob wants the cup and Carol the apple, so get it sorted.", CELL),
    # (y) 'action' before no doing
    ("can we action Priya?", OFFICE),
    # (z) the pronoun against the title or the number; a surface not had; another recipient;
    # the handover negated
    ("Mrs Khan hasn't had his magazine, take it over.", WARD),
    ("Mrs Khan hasn't had her magazine, take them over.", WARD),
    ("Mrs Khan hasn't had her trolley, take it over.", WARD),
    ("Mrs Khan hasn't had her magazine, take it over to Mr Lee.", WARD),
    ("Mrs Khan hasn't had her magazine, don't take it over.", WARD),
]


@pytest.mark.parametrize(("text", "scene"), REFUSED)
def test_near_sentences_stay_refused(text: str, scene: object) -> None:
    assert_refused(text, scene)  # type: ignore[arg-type]
