"""Session-29 phrasings of issue 12 (engineer 12s): the speaker talking about themself in ways
that ask nothing — their own next act said with a verb of the grammar, owning a slip, what they
are doing with another surface, being told or asked —, and the kinds met with them: a gapped
'and Bob also the apple', 'Bob wants his crisps' beside another person, 'on the teacher's desk',
'not fussed which', 'parched after the heat'. Each rule with the near forms it must read and the
near forms it must refuse or read differently (docs/grounding.md, "Session 29 (engineer 12s)")."""

from __future__ import annotations

from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
)

FOUR = load_scene(ROOT / "examples/scenes/4-2.yaml")  # bottle, chips, cup, apple; Person A, B
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips; Alice, Bob

# -- the speaker's own next act (normalise.py _speaker_plan29s) ---------------------------------


def test_speaker_next_act_with_a_verb_of_the_grammar() -> None:
    assert_reads(
        "Stapler to Sam and the black pen into the box and then I can get the tape measure out.",
        "stapler>B & pen_black@box",
        OFFICE,
    )
    assert_reads(
        "Drill on the bench then torch to Jess and I'll give you a trim after.",
        "drill@bench ; torch>B",
        WORKSHOP,
    )
    assert_reads(
        "Could you put the bottle on the shelf, then I'll get the next patient through, thanks.",
        "bottle@shelf",
        CELL,
    )
    assert_reads(
        "Would you give Carol the cup? Thank you, I'm only here to take bloods.", "cup>C", CELL
    )
    assert_reads(
        "First Alice gets the bottle and then Bob gets the chips and after that I'm back to "
        "re-covering this armchair.",
        "bottle>A ; chips>B",
        TWO,
    )


def test_speaker_next_act_near_forms_stay_refused() -> None:
    # the speaker's act on what the request names, or a pronoun for it: not taken off
    assert_refused("Give Bob the cup and then I'll get the bottle.", CELL)
    assert_refused("Give Bob the cup and then I'll take it.", CELL)
    assert_refused("Give Bob the cup and then I can get the other one.", CELL)
    assert_refused("Give Bob the cup and then I'll give him both.", CELL)
    # the speaker as the recipient, or wanting: a request for the speaker
    assert_refused("Give Bob the cup and then I'll have the bottle after.", CELL)
    assert_refused("Give Bob the cup and after that I need the tape measure.", CELL)
    # a request to the hearer, not the speaker's act
    assert_refused("Give Bob the cup and then get the tape measure out.", CELL)


def test_every_and_not_a_thing_in_a_speaker_remark() -> None:
    assert_reads(
        "Could Carol have the red mug? I'd do it myself but I've got gold leaf stuck to every "
        "finger.",
        "mug_red>C",
        CELL,
    )
    assert_reads(
        "Bottle to Person A, please, I can't touch a thing with ink on these nibs.",
        "bottle>A",
        FOUR,
    )
    # 'every one', 'every thing', 'each of them', and 'a thing' without a negation stay held
    assert_refused("Could Carol have the red mug? I'd do it but I've got every one.", CELL)
    assert_refused("Could Carol have the red mug? I'd do each of them myself.", CELL)
    assert_refused("Bottle to Person A, I can touch a thing with ink.", FOUR)


# -- the speaker owning a slip (normalise.py _slip_owned29s) ------------------------------------


def test_slip_owned_after_a_correction_or_as_its_cue() -> None:
    assert_reads("Apple to Person A, no, sorry, to Person B, I make mistake.", "apple>B", FOUR)
    assert_reads("Apple to Person A, no, to Person B, I made a mistake.", "apple>B", FOUR)
    assert_reads(
        "Give Ava the red block, oh silly me, she wants the green one.", "block_green>C", NURSERY
    )
    assert_reads("Give Ava the red block, silly me, the green one.", "block_green>C", NURSERY)
    # a cue already before it: the earlier rules' reading stands
    assert_reads("The chips, no, the bottle, silly me, to Person A.", "bottle>A", FOUR)


def test_slip_owned_near_forms() -> None:
    # no correction before the closing slip: what would it be owning?
    assert_refused("Apple to Person A, to Person B, I make mistake.", FOUR)
    # more after the slip than its correction: refused as the cue rule refuses it
    assert_refused("Give Ava the red block, silly me, and the teddy to Lily.", NURSERY)
    # a slip with nothing before it, or closing a request with no correction
    assert_refused("Oh silly me, give Ava the red block.", NURSERY)
    assert_refused("Give Ava the red block, silly me.", NURSERY)


# -- told and asked (normalise.py _ASIDES22, _asked_me29s) --------------------------------------


def test_told_me_with_when_and_asked_me_for() -> None:
    assert_reads(
        "Zoe wants the ruler and Noah needs the glue stick, they told me while I was mopping.",
        "ruler>C & glue>B",
        CLASSROOM,
    )
    assert_reads("Bob wants the apple, he told me before.", "apple>B", CELL)
    assert_reads("Person A has asked me twice now for the chips.", "chips>A", FOUR)
    assert_reads("Person A keeps asking me for the chips.", "chips>A", FOUR)


def test_told_and_asked_near_forms() -> None:
    # the speaker's 'while' clause naming the scene, or more after 'told me': not an aside
    assert_refused("Zoe wants the ruler, they told me while I was mopping the desk.", CLASSROOM)
    assert_refused("Bob wants the apple, he told me before I left.", CELL)
    # 'me' asked, then another person gets it: the conflict stays refused
    assert_refused("Person A has asked me for the chips, give them to Person B.", FOUR)
    # the speaker asked for something: 'me' is the asker's object, no scene person asks
    assert_refused("Someone has asked me for the chips.", FOUR)


# -- a gapped clause with 'also' (normalise.py _gapped_also29s) ---------------------------------


def test_gapped_also() -> None:
    assert_reads(
        "Carol would like the blue mug, and Bob also the apple, he told me before.",
        "mug_blue>C & apple>B",
        CELL,
    )
    assert_reads("Carol would like the blue mug, and Bob also the apple.", "mug_blue>C & apple>B")
    # without the rule 'also' is 'the apple too', and the blue mug went to Bob as well: refused
    assert_refused("Carol would like the blue mug, and Bob also.", CELL)
    # an object before 'also' is no gapped clause's person: read as before (all to Carol)
    assert_reads(
        "Give Carol the blue mug, and the cup also the apple.", "mug_blue>C & cup>C & apple>C"
    )


# -- 'his' / 'her' after a person's want (normalise.py _own_want29s) ----------------------------


def test_own_want_possessive() -> None:
    assert_reads(
        "First Alice gets her bottle and then Bob wants his crisps.",
        "bottle>A ; chips>B",
        TWO,
    )
    assert_reads("Alice wants the cup and Bob wants his apple.", "cup>A & apple>B", CELL)
    # two mugs: 'his mug' may pick one; left to the grammar, which refuses
    assert_refused("Alice wants the cup and Bob wants his mug.", CELL)


# -- the speaker busy with another surface (normalise.py _surface_busy29s) ----------------------


def test_surface_busy_after_a_placement() -> None:
    three_pens = "pen_black@box & pen_blue@box & pen_red@box"
    assert_reads("All three pens in the box, please, I'm clearing the desk.", three_pens, OFFICE)
    assert_reads(
        "All three pens go in the box, I need the desk for my pattern paper.", three_pens, OFFICE
    )
    assert_reads(
        "Put the stapler in the box, I need the desk clear for the cloth.", "stapler@box", OFFICE
    )
    assert_reads(
        "Both books on the desk, I need to do the shelves.",
        "book_red@desk & book_green@desk",
        CLASSROOM,
    )
    assert_reads(
        "Could the apple go on the table, I've got puppets all over the shelf?", "apple@table", CELL
    )


def test_surface_busy_near_forms() -> None:
    # the surface the request uses: contradictory, refused
    assert_refused("All three pens in the box, please, I'm clearing the box.", OFFICE)
    # no placement before it: 'I need the desk' is the speaker's want
    assert_refused("Give Sam the stapler, I need the desk.", OFFICE)
    # an object in the remark: it may ask for it
    assert_refused("Put the stapler in the box, I need the desk for the red pen.", OFFICE)
    # another verb ('I think the shelf is better'): a correction, not a reason
    assert_refused("Could the apple go on the table, I think the shelf is better?", CELL)


# -- a person's surface (normalise.py _owned_surface29s) ----------------------------------------


def test_owned_surface() -> None:
    assert_reads(
        "Both books on the teacher's desk, I need to do the shelves.",
        "book_red@desk & book_green@desk",
        CLASSROOM,
    )
    assert_reads("Put the globe on Zoe's desk.", "globe@desk", CLASSROOM)
    # 'the student' is two people, 'the caretaker' no one: left, refused
    assert_refused("Put the globe on the student's desk.", CLASSROOM)
    assert_refused("Put the globe on the caretaker's desk.", CLASSROOM)


# -- 'not fussed which' (normalise.py _not_fussed29s) -------------------------------------------


def test_not_fussed_which() -> None:
    either = "mug_red>C | mug_blue>C"
    assert_reads("Give Carol one of the mugs, she really doesn't care which.", either)
    assert_reads("Give Carol either of the mugs, she's not fussed which.", either)
    assert_reads("One of the mugs for Carol, red or blue, not bothered.", either)
    assert_reads("One of the mugs for Carol, red or blue, I'm not fussy.", either)
    # nothing open: the request as said
    assert_reads("Give Carol the red mug, she's not fussed.", "mug_red>C")
    # 'not fussed' with more in its clause ('not fussed about the cup') is a negation: refused
    assert_refused("Give Carol one of the mugs, she's not fussed about the cup.", CELL)


# -- what brought a state on (normalise.py _state_cause29s) -------------------------------------


def test_state_cause_taken_off() -> None:
    assert_reads("Person A's parched after the heat, run the bottle over to her.", "bottle>A", FOUR)
    assert_reads("Bob's thirsty from the ride, so take him over the bottle.", "bottle>B", TWO)
    assert_reads(
        "Person A's gasping after her run, she really needs that bottle.", "bottle>A", FOUR
    )
    assert_reads(
        "Person A's peckish after the audiology clinic, so the apple or else the chips, she's "
        "not bothered which.",
        "apple>A | chips>A",
        FOUR,
    )


def test_state_cause_near_forms() -> None:
    # a cause naming the scene, or a pronoun or verb that could be about its objects: left
    assert_refused("Person A's hungry after the apple, give her the chips.", FOUR)
    assert_refused("Person A's thirsty after that, give her the bottle.", FOUR)
    assert_refused("Person A's thirsty after she gets the chips, give her the bottle.", FOUR)


# -- the kind's objects listed by colour or size (normalise.py _kind_adjectives29s) --------------


def test_kind_listed_by_adjectives() -> None:
    assert_reads("Both mugs, red and blue, up on the shelf.", "mug_red@shelf & mug_blue@shelf")
    assert_reads("Give Alice a mug, red or blue.", "mug_red>A | mug_blue>A")
    assert_reads(
        "Load the three boxes onto the belt, small, medium and large.",
        "box_small@conveyor & box_medium@conveyor & box_large@conveyor",
        DEPOT,
    )
    assert_reads(
        "Hand Jess a spanner, big or small, she's only tightening a bolt.",
        "spanner_small>B | spanner_large>B",
        WORKSHOP,
    )
    assert_reads(
        "Both cups, green and white, onto the tray.", "cup_green@tray & cup_white@tray", LAB
    )


def test_kind_listed_near_forms() -> None:
    # two of three after 'the three boxes', or after 'the boxes': which is meant is unclear
    assert_refused("Load the three boxes onto the belt, small and large.", DEPOT)
    assert_refused("Load the boxes onto the belt, small and large.", DEPOT)
    # a choice after a plural, a list after one object, a choice of two of three
    assert_refused("Give Alice both mugs, red or blue.")
    assert_refused("Give Alice the red mug, red and blue.")
    assert_refused("Load a box onto the belt, small or large.", DEPOT)
    # other objects in the clause: the list could be about them
    assert_refused("Give Alice the cup and both mugs, red and blue.")


# -- corrections: 'wrong one', 'I meant', 'nope', a slip after the cue, "it's Person B's" -------


def test_correction_cue_forms() -> None:
    assert_reads(
        "Hand the chips to Person A, whoops, wrong one, I meant Person B.", "chips>B", FOUR
    )
    assert_reads("Chips for Person A, oops, wrong one, Person B.", "chips>B", FOUR)
    assert_reads("Chips for Person A, wrong one, Person B.", "chips>B", FOUR)
    assert_reads("Hand the chips to Person A, whoops, I meant Person B.", "chips>B", FOUR)
    assert_reads("Spoon to Omar, nope, to Dana, she's stirring the samples.", "spoon>A", LAB)
    assert_reads(
        "Cup over to Person A... nope, I've read the ticket wrong, it's Person B's.", "cup>B", FOUR
    )
    assert_reads("Cup over to Person A, no, it's Person B's.", "cup>B", FOUR)
    assert_reads(
        "Magazine to Mr Lee, oh I've got that wrong, it was Mrs Khan who asked for it.",
        "magazine>C",
        WARD,
    )


def test_correction_cue_near_forms() -> None:
    # 'wrong way round' swaps; 'wrong one' with nothing after it corrects to nothing
    assert_refused("Chips for Person A, oops, wrong way round, Person B.", FOUR)
    assert_refused("Chips for Person A, oops, wrong one.", FOUR)
    # 'nope' opening the text answers something: not a correction
    assert_refused("Nope, cup to Person A.", FOUR)
    # "it's Person B's" without a correction before it; a cleft naming no one of the scene
    assert_refused("Cup over to Person A, it's Person B's.", FOUR)
    assert_refused("Magazine to Mr Lee, no, it was the doctor who asked for it.", WARD)
    # 'no' then 'body': 'nobody' is no cue followed by 'body'
    assert_refused("Hand the chips to Person A, whoops, nobody.", FOUR)


# -- '<role> here' and kindly conditions (normalise.py _here_i_am29s, _kindly_if29s) ------------


def test_self_introduction_with_here() -> None:
    assert_reads(
        "Hiya, zookeeper here for the school visit, the penguins are still in the van. Could you "
        "be a star and hand Mrs Ortiz the glue stick? Ta.",
        "glue>A",
        CLASSROOM,
    )
    assert_reads(
        "Gardener here again, sorry, the globr wants moving onto the desk, please.",
        "globe@desk",
        CLASSROOM,
    )


def test_self_introduction_near_forms() -> None:
    # a person of the scene ('teacher' is Mrs Ortiz) saying who they are: 'me' is them, refused
    assert_refused("Teacher here, give me the globe.", CLASSROOM)
    # 'here' after an object is where it is (or an unknown name), not who speaks
    assert_refused("The globe here, Zoe.", CLASSROOM)
    # a self-introduction with a held word ('it here') is left
    assert_refused("Put it here, then hand Mrs Ortiz the glue stick.", CLASSROOM)


def test_kindly_conditions() -> None:
    assert_reads(
        "Um, if it's all the same to you, the bottle over to Person B, please.", "bottle>B", FOUR
    )
    assert_reads("Kindly give the bottle to Person A, if okay with you.", "bottle>A", FOUR)
    assert_reads(
        "Um, sorry, only if it isn't too much trouble, the apple across to Person A, please.",
        "apple>A",
        FOUR,
    )
    assert_reads(
        "I'm only visiting, so forgive me if I get this wrong, but would you be able to give the "
        "banana to Emma?",
        "banana>C",
        LAB,
    )
    assert_reads(
        "Give the banana to Emma, if that's okay with you, and the spoon to Omar.",
        "banana>C & spoon>B",
        LAB,
    )


def test_kindly_conditions_near_forms() -> None:
    # a condition about the scene or the moment is a condition: refused
    assert_refused("Give the banana to Emma if it's clean.", LAB)
    assert_refused("Give the banana to Emma, if Emma is there.", LAB)
    assert_refused("If it's all the same to Emma, give her the banana.", LAB)


# -- 'would you mind letting', 'tidy … away into', 'ever so grateful' (_kindly_verbs29s) --------


def test_kindly_verbs_and_gratitude() -> None:
    assert_reads("Would you mind awfully letting Person B have the chips?", "chips>B", FOUR)
    assert_reads(
        "Would you mind awfully tidying the red pen away into the box?", "pen_red@box", OFFICE
    )
    assert_reads(
        "If you wouldn't mind terribly, the notepad to Sam, and the stapler to Priya, ever so "
        "grateful.",
        "notebook>B & stapler>A",
        OFFICE,
    )
    assert_reads("Give Sam the notepad, much obliged.", "notebook>B", OFFICE)


def test_kindly_verbs_near_forms() -> None:
    # tidying away with no place, or a surface tidied away: refused
    assert_refused("Tidy the red pen away.", OFFICE)
    assert_refused("Tidy the desk away into the box.", OFFICE)
    # gratitude for an object says more than thanks; 'not mind' with an object is a negation
    assert_refused("Give Sam the notepad, grateful for the stapler.", OFFICE)
    assert_refused("If you wouldn't mind the noise, give Sam the notepad.", OFFICE)


# -- a person taken up by a pronoun (normalise.py _dislocated29s) -------------------------------


def test_dislocated_person() -> None:
    assert_reads(
        "Bottle goes to Person A, and Person B, she gets the chips.", "bottle>A & chips>B", FOUR
    )
    assert_reads(
        "Right. Person A, she gets the bottle. Person B, the chips are his. I'm back at the loom.",
        "bottle>A & chips>B",
        FOUR,
    )


def test_dislocated_person_near_forms() -> None:
    # a pronoun that cannot be the person (by title): the chips are someone else's
    assert_refused("Mr Lee, the jug is hers.", WARD)
    # the speaker's own: not the person's
    assert_refused("Person B, the chips are mine.", FOUR)


# -- a correction taken back at once: 'no, wait, yes' (normalise.py _no_yes29s) -----------------


def test_no_then_yes() -> None:
    assert_reads(
        "Bottle to Person A, no, wait, yes, that's right, Person A, carry on.", "bottle>A", FOUR
    )
    assert_reads(
        "Give Person A the bottle, no wait, yeah, that's right, the bottle.", "bottle>A", FOUR
    )
    assert_reads("Bottle to, no hang on, yes, Person A, it's only her.", "bottle>A", FOUR)
    assert_reads("Person A, the bottle — no, yes, the bottle, that's right.", "bottle>A", FOUR)


def test_no_then_yes_near_forms() -> None:
    # another name after 'yes', or more after it: refused
    assert_refused("Bottle to Person A, no, wait, yes, Person B.", FOUR)
    assert_refused("Bottle to Person A, no, yes, Person A, and the chips to Person B.", FOUR)
    # (another object after 'yeah' is the correction the earlier rules read: "…, no wait, yeah,
    # the chips" is the chips to Person A, as on main)
    assert_reads("Give Person A the bottle, no wait, yeah, the chips.", "chips>A", FOUR)


# -- 'not for P, it's for Q'; 'P asked for X and Q for Y' (_not_for_but29s, _asked_and29s) -------


def test_not_for_one_but_another() -> None:
    assert_reads(
        "The chips are not for Person A, I tell you, they are for Person B.", "chips>B", FOUR
    )
    assert_reads(
        "The chips aren't for Person A, they're for Person B, she's the one who paid.",
        "chips>B",
        FOUR,
    )
    assert_reads(
        "Person B asked for the bottle and Person A for the chips.", "bottle>B & chips>A", FOUR
    )
    assert_reads(
        "sam's asked for the notepad and priya for the stapler, i'm just trimming the spines",
        "notebook>B & stapler>A",
        OFFICE,
    )


def test_not_for_one_but_another_near_forms() -> None:
    # the same person twice, or no second clause: a negation, refused
    assert_refused("The chips aren't for Person A, they're for Person A.", FOUR)
    assert_refused("The chips aren't for Person A.", FOUR)
    assert_refused("The chips aren't for Person A, and the bottle is for Person B.", FOUR)
    # 'for' after a person who asked nothing: two recipients, refused
    assert_refused("Person B has the bottle and Person A for the chips.", FOUR)


# -- what a placement is for: 'ready for …' (normalise.py _ready_for29s) ------------------------


def test_ready_for_after_a_placement() -> None:
    assert_reads(
        "Put the tape on the belt, and the gloves too, both of them, ready for the next shift.",
        "tape@conveyor & gloves@conveyor",
        DEPOT,
    )
    assert_reads("Put the globw on the desk ready for geography.", "globe@desk", CLASSROOM)


def test_ready_for_near_forms() -> None:
    # ready for a person, or for 'it': who or what it is for may be asked; no placement: left
    assert_refused("Put the tape on the belt, ready for Tom.", DEPOT)
    assert_refused("Put the tape on the belt, ready for it.", DEPOT)
    assert_refused("Give Tom the tape, ready for the next shift.", DEPOT)
    assert_refused("Put the globe on the desk ready for the next one.", CLASSROOM)


# -- 'excuse the flour on everything'; "(I've) only just come off …" (_excuse_the29s) -----------


def test_excuse_the_mess_and_an_elided_i() -> None:
    assert_reads(
        "Morning! I've been up since four with the sourdough, so excuse the flour on everything. "
        "Would you be a darling and bring Carol the red mug? Cheers, my love.",
        "mug_red>C",
    )
    assert_reads("Give Carol the red mug, excuse the mess.", "mug_red>C")
    assert_reads(
        "Morning all! Only just come off the gallops, so forgive the mud on my boots. Could you be "
        "a sweetheart and pass Person A that bottle?",
        "bottle>A",
        FOUR,
    )


def test_excuse_the_mess_near_forms() -> None:
    # excusing an object of the scene: left, refused
    assert_refused("Excuse the cup, give Carol the red mug.")
    # 'just come back with the bottle' is a request to come back (no verb of the grammar)
    assert_refused("Just come back with the bottle.", FOUR)


# -- a sentence opening a correction that says it is one (normalise.py _opens_a_fix29s) ---------


def test_sentence_opening_an_owned_correction() -> None:
    assert_reads("Bottle to Person B. Hang on, I misspoke, chips to Person B.", "chips>B", FOUR)
    assert_reads("Bob wants the cup. Sorry, my mistake, it's the apple he wants.", "apple>B")
    assert_reads(
        "Person A wants the bottle. Sorry, I misheard her, it's the chips she wants.",
        "chips>A",
        FOUR,
    )
    assert_reads("Lemon to Mr Novak. Hang on, not the lemon, the salt.", "salt>C", KITCHEN)
    assert_reads("The banana for Omar. Actually, change that to Dana.", "banana>A", LAB)


def test_sentence_opening_a_correction_near_forms() -> None:
    # the cue alone could correct or add: refused as before
    assert_refused("Bottle to Person B. Hang on, chips to Person B.", FOUR)
    # 'not' an object the sentence before does not name; nothing after the owned slip
    assert_refused("Lemon to Mr Novak. Hang on, not the knife, the salt.", KITCHEN)
    assert_refused("Bottle to Person B. Sorry, my mistake.", FOUR)
