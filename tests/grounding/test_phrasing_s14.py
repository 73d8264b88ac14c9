"""Session-14 phrasings of issue 12 (blind12's causes and the classes around them), each as a
family checked against an oracle built from the words the family is made of, and near forms
that must stay refused."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.grounding.lexicon import slip_cost
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    SCENES,
    WARD,
    WORKSHOP,
    assert_refused,
    plain_request,
)
from tests.grounding.helpers import assert_reads as assert_means

# -- words that cannot change who gets what ------------------------------------------------------
#
# The oracle: the plain request's own reading. Each opener and closer is of a listed class (the
# hearer as a group, courtesy conditions, apologies for asking, praise of the hearer, address,
# "listen", the speaker saying it is them again): it names nothing in the scene and holds no
# negation, count, choice or order.

OPENERS = [
    "",
    "Y'all ",
    "Could you all ",
    "Would ye ",
    "Can yous ",
    "You guys mind ",
    "If it's no trouble, ",
    "If it isn't too much bother, love, ",
    "If it's not too much to ask, ",
    "Sorry to bother you, ",
    "So sorry to be a pain, but ",
    "Terribly sorry to trouble you, ",
    "Hi! So sorry to interrupt, ",
    "You're a star, ",
    "Oh you're an absolute gem, ",
    "Me again, sorry! ",
    "It's me again. ",
    "Only me! ",
    "Listen, ",
    "ok listen ",
    "Right, listen up: ",
    "Pet, ",
]
CLOSERS = [
    "",
    ", nice one",
    ", good man",
    ", cheers mate",
    ", ta love",
    ", thanks pet",
    ", you're a star",
    ", there's a good robot",
    ". Bless you.",
    ". Appreciate you!",
    ", that'd be grand",
    ", it'd be a great help",
    " if it's going",
    " if it's free",
    ", well done",
    " thats it",
]


def _opened(opener: str, request: str) -> str:
    if opener.endswith("mind "):  # "You guys mind giving …"
        return opener + request.replace("give ", "giving ", 1)
    return opener + request


@settings(max_examples=150, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 5),
    st.sampled_from(OPENERS),
    st.sampled_from(CLOSERS),
)
def test_courtesy_and_address_leave_the_request(
    scene: Scene, k: int, opener: str, closer: str
) -> None:
    request, want = plain_request(scene, k)
    assert_means(_opened(opener, request) + closer, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("If it's on the shelf, give Bob the apple", CELL),
        ("If Omar isn't busy, give him the spoon", LAB),
        ("Carol would love the red mug if Bob doesn't want it", CELL),
        ("You're a star, give me the cup", CELL),
        ("Y'all give me the apple", CELL),
        ("Give ye the salt", KITCHEN),
        ("Me again, give me the spoon", LAB),
        ("It's me again, the lemon is for me", KITCHEN),
        ("Listen to Sam", OFFICE),
        ("give alice thats it", CELL),
        ("Give Bob the cup. Sorry, also give him the apple.", CELL),
        # a closing that could pick an object is not a closing
        ("Give Bob a mug, the good one", CELL),
        ("You're Bob, give Carol the cup", CELL),
    ],
)
def test_near_forms_of_courtesy_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- frames read as their plain forms -------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # a person 'after' an object wants it
        ("Jess is after the torch", "torch>B", WORKSHOP),
        ("Marco's after the tongs and the salt", "tongs>A & salt>A", KITCHEN),
        ("Omar's after a cup", "cup_green>B | cup_white>B", LAB),
        ("Mr Lee's after his tablets", "pills>B", WARD),
        # a want of a placement
        ("Dana wants the bowl put in the sink", "bowl@sink", LAB),
        ("Tom needs the medium box loaded onto the pallet", "box_medium@pallet", DEPOT),
        (
            "Kofi needs the drill and the hammer moved onto the bench",
            "drill@bench & hammer@bench",
            WORKSHOP,
        ),
        # 'they' for the one person before the condition
        (
            "Give Sam the stapler and once they have it, give Priya the notebook",
            "stapler>B ; notebook>A",
            OFFICE,
        ),
        # a run-on at 'now', the person's whereabouts a remark
        ("Zoe's finished now she needs the globe", "globe>C", CLASSROOM),
        (
            "So Lily's in her high chair now she wants the beaker and Ava wants the red block",
            "beaker>A & block_red>C",
            NURSERY,
        ),
        # a kind said alone heads the notes after it; a person given nothing
        ("Cups. Green one to Dana, white one to Emma.", "cup_green>A & cup_white>C", LAB),
        ("Books. Red one to Noah. Green one to Zoe.", "book_red>B & book_green>C", CLASSROOM),
        ("Jess gets the torch. Kofi, nothing.", "torch>B", WORKSHOP),
        ("Omar the bowl. Dana, nothing. Emma the banana.", "bowl>B & banana>C", LAB),
        # handy: the robots' pick
        ("Give Dana whichever cup is nearer", "cup_green>A | cup_white>A", LAB),
        ("Whichever plate is nearest, give it to Lena", "plate_white>B | plate_blue>B", KITCHEN),
        ("Whatever cup's nearest, put it in the sink", "cup_green@sink | cup_white@sink", LAB),
        # each, either, both of them
        (
            "Both patients need a blanket, one each",
            "(blanket_blue>B & blanket_grey>C) | (blanket_grey>B & blanket_blue>C)",
            WARD,
        ),
        ("Noah or Zoe, either one can have the globe", "globe>B | globe>C", CLASSROOM),
        ("Give Kofi both of them, the hammer and the drill", "hammer>A & drill>A", WORKSHOP),
        ("Put both of them in the sink, the bowl and the spoon", "bowl@sink & spoon@sink", LAB),
        # counts
        ("Priya's taking all 3 pens", "pen_black>A & pen_blue>A & pen_red>A", OFFICE),
        (
            "Put the pens in the box, all three of them",
            "pen_black@box & pen_blue@box & pen_red@box",
            OFFICE,
        ),
        (
            "The spanners go on the bench, both of them",
            "spanner_small@bench & spanner_large@bench",
            WORKSHOP,
        ),
        ("Just the one cup for Omar, the green one", "cup_green>B", LAB),
        ("Just the one pen for Sam", "pen_black>B | pen_blue>B | pen_red>B", OFFICE),
        (
            "Give each of the two people one thing: the tape to Mia, the gloves to Tom",
            "tape>A & gloves>B",
            DEPOT,
        ),
        ("Two pens for Sam, the red and the blue", "pen_red>B & pen_blue>B", OFFICE),
        (
            "Apart from the two plates, everything goes on the counter",
            "knife@counter & lemon@counter & salt@counter & tongs@counter",
            KITCHEN,
        ),
        # corrections
        ("Give Omar the banana rather than the spoon", "banana>B", LAB),
        ("Put the bowl in the sink rather than on the tray", "bowl@sink", LAB),
        (
            "Put the knife on the rack, actually the counter would be better",
            "knife@counter",
            KITCHEN,
        ),
        ("Spoon on the tray — hang on, the sink's better", "spoon@sink", LAB),
        ("The tape is for Mia. Sorry, my mistake, it's for Tom.", "tape>B", DEPOT),
        ("The teddy's for Lily, I mean it's for Ava", "teddy>C", NURSERY),
        ("The stapler goes to Sam, I mean it goes in the box", "stapler@box", OFFICE),
        ("Give Tom the gloves, I mean give them to Mia", "gloves>A", DEPOT),
        # typos: a surname with two letters swapped after its title; ordinary typos
        ("Give Mrs Kahn the magazine", "magazine>C", WARD),
        ("Give Mrs Otriz the ruler", "ruler>A", CLASSROOM),
        ("Give Kofi the hamer", "hammer>A", WORKSHOP),
        ("Jess needs the drll", "drill>B", WORKSHOP),
        ("Hand Marco the knif", "knife>A", KITCHEN),
        ("Marco wants the knive", "knife>A", KITCHEN),
        ("Tom wants the gloes", "gloves>B", DEPOT),
        ("Sam needs the staplr", "stapler>B", OFFICE),
        ("Put the apple on the sheld", "apple@shelf", CELL),
    ],
)
def test_frames_read_as_their_plain_forms(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Jess is after Kofi", WORKSHOP),
        ("Tom needs the medium box loaded onto Mia", DEPOT),
        ("When they've got the stapler, give Priya the notebook", OFFICE),
        ("Mr Lee's awake now she wants the jug", WARD),
        ("Lily's in her high chair now, put the beaker there", NURSERY),
        ("Books. Red one to Noah. Red one to Zoe.", CLASSROOM),
        ("Mugs. Green one to Alice.", CELL),
        ("Ruth, nothing. Ruth, the jug.", WARD),
        ("Mr Lee, nothing.", WARD),
        ("Give Sam whichever ruler is closest", OFFICE),
        ("Both patients need the jug, one each", WARD),
        ("Both students need a ruler, one each", CLASSROOM),
        ("Noah or Zoe, both can have the globe", CLASSROOM),
        ("Bob should get both of them, the bottle, the crisps and the shelf", CELL),
        ("Give Kofi both of them", WORKSHOP),
        ("Give Kofi both of them, the hammer, the drill and the torch", WORKSHOP),
        ("Priya's taking all 4 pens", OFFICE),
        ("Mia gets the boxes, all two of them", DEPOT),
        ("Put the pens in the box, both of them", OFFICE),
        ("Just the one cup for Omar, the red one", LAB),
        ("Give each of the three people one thing: the cup to Alice, the apple to Bob", CELL),
        ("Two boxes for Mia, the small one", DEPOT),
        ("Two boxes for Mia, the small and the huge", DEPOT),
        ("Apart from the three plates, everything goes on the counter", KITCHEN),
        ("Give Carol the cup rather than the cup", CELL),
        ("Put the bowl in the sink rather than in the sink", LAB),
        ("Spoon on the tray — hang on, the sink's dirty", LAB),
        ("The tape is for Mia. My mistake.", DEPOT),
        ("The stapler goes to Sam, I mean it goes", OFFICE),
        # a typo with a letter the scene's word lacks that a common word has ('pillows')
        ("Give Mr Lee the pillws", WARD),
        ("Mr Lee wants the pillos", WARD),
    ],
)
def test_near_forms_of_the_frames_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_slip_costs() -> None:
    assert slip_cost("pillws", "pills") == 1.5  # a 'w' put in beside its neighbour 's'
    assert slip_cost("pillws", "pillows") == 1.0  # an 'o' left out
    assert slip_cost("botle", "bottle") == 0.5  # a doubled letter typed once
    assert slip_cost("bottlle", "bottle") == 1.0  # a letter typed twice
    assert slip_cost("crips", "crisp") == 1.0  # two neighbours swapped
    assert slip_cost("knif", "knit") == 1.5  # a neighbouring key
    assert slip_cost("knive", "knife") == 1.5
    assert slip_cost("bxttle", "bottle") == 2.5  # any other letter
    assert slip_cost("cup", "cup") is None
    assert slip_cost("cup", "apple") is None


# -- classes a new writer brings (the session's own probes, across scenes) -------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Can you do me a kindness and bring Mr Lee his tablets", "pills>B", WARD),
        ("do us a favour and put the bowl in the sink", "bowl@sink", LAB),
        ("Mia could really do with the scanner right about now", "scanner>A", DEPOT),
        ("new line give omar the spoon full stop", "spoon>B", LAB),
        (
            "would you be a darling and load the small box onto the pallet",
            "box_small@pallet",
            DEPOT,
        ),
        ("Ruth will be wanting the thermometer", "thermometer>A", WARD),
        ("Zoe would be wanting the green book", "book_green>C", CLASSROOM),
        (
            "Marco gets the knife, Lena gets the tongs, and that's the lot",
            "knife>A & tongs>B",
            KITCHEN,
        ),
        ("Right then, jug to Mrs Khan, and Bob's your uncle", "jug>C", WARD),
        ("Give Bob the cup, eh", "cup>B", CELL),
        ("Put the cup on the shelf, there you go", "cup@shelf", CELL),
        ("Could you slip Bob the chips", "chips>B", CELL),
        ("Bung the cup over to Bob", "cup>B", CELL),
        ("Pile the mugs on the table", "mug_red@table & mug_blue@table", CELL),
        ("Bob wants the cup, if I remember right", "cup>B", CELL),
        ("Bob mentioned he'd like the cup", "cup>B", CELL),
        ("Like I said before, give Bob the cup", "cup>B", CELL),
        ("Per Bob's request, give him the cup", "cup>B", CELL),
        ("Bob's request: the cup", "cup>B", CELL),
        ("Order for Bob: one cup", "cup>B", CELL),
        ("Bob ordered the cup", "cup>B", CELL),
        # "The cup is Bob's" (was cup>B) is refused naming both readings since session 33: alone
        # it may say whose the cup is, asking nothing (the lead's probe "The drill is Jess's.";
        # tests/grounding/test_phrasing_s33s.py); with 'please' it allots
        ("The cup is Bob's, please", "cup>B", CELL),
        ("Carol, the apple is yours", "apple>C", CELL),
        ("OK Google, give Lena the salt", "salt>B", KITCHEN),
        ("Would you mind awfully passing Mrs Khan the water jug", "jug>C", WARD),
        ("Mrs Khan was wondering if she might have the water jug", "jug>C", WARD),
        ("Mrs Khan would be ever so grateful for the water jug", "jug>C", WARD),
        ("The plan is to give Mrs Khan the water jug", "jug>C", WARD),
        ("Give the jug to her, Mrs Khan I mean", "jug>C", WARD),
        ("Give her the jug - Mrs Khan", "jug>C", WARD),
        ("Mrs Khan (bed 3) wants the jug", "jug>C", WARD),
        ("Mrs Khan, bed 3, wants the jug", "jug>C", WARD),
        ("Give Mrs Khan (bed 2) the jug and Mr Lee (bed 3) the pills", "jug>C & pills>B", WARD),
        # said by someone learning English, by someone older, in other Englishes
        ("Is possible to give Emma the white cup?", "cup_white>C", LAB),
        ("I am asking you to put the bowl in sink", "bowl@sink", LAB),
        ("The sponge, please to put in the sink", "sponge@sink", LAB),
        ("Emma is wanting that you give her the white cup", "cup_white>C", LAB),
        ("Dana must to have the banana", "banana>A", LAB),
        (
            "Now then dear, I'd like the water jug to go to Mrs Khan if that's no trouble",
            "jug>C",
            WARD,
        ),
        ("My dear, would you kindly see that Mr Lee gets his magazine", "magazine>B", WARD),
        ("Would you see Mrs Khan gets the jug", "jug>C", WARD),
        ("Now, where was I? Oh yes, the jug to Mrs Khan", "jug>C", WARD),
        ("What was it... ah, the jug for Mrs Khan", "jug>C", WARD),
        ("The jug. For Mrs Khan. Thank you, dear.", "jug>C", WARD),
        ("Reckon Lena wants the lemon", "lemon>B", KITCHEN),
        ("Lena reckons she wants the lemon", "lemon>B", KITCHEN),
        ("Howay, the salt to Lena", "salt>B", KITCHEN),
        ("G'day, could the knife go to Marco", "knife>A", KITCHEN),
        ("No worries, knife to Marco", "knife>A", KITCHEN),
        ("Knife to Marco, no dramas", "knife>A", KITCHEN),
        ("Can I get the salt for Lena", "salt>B", KITCHEN),
        ("I'll have the salt for Lena", "salt>B", KITCHEN),
        # notes of a kind for a person, 'the lot', 'any old', 'when you're done' at the end
        ("Any old pen for Sam", "pen_black>B | pen_blue>B | pen_red>B", OFFICE),
        ("A pen for Sam, any colour", "pen_black>B | pen_blue>B | pen_red>B", OFFICE),
        ("A pen for Sam, the red one", "pen_red>B", OFFICE),
        ("Stapler in the box when you're done", "stapler@box", OFFICE),
        (
            "Give Priya the lot",
            "pen_black>A & notebook>A & pen_blue>A & stapler>A & pen_red>A",
            OFFICE,
        ),
        ("Priya can have the lot apart from the pens", "notebook>A & stapler>A", OFFICE),
    ],
)
def test_classes_a_new_writer_brings(text: str, want: str, scene: Scene) -> None:
    assert_means(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Give him the jug - Mrs Khan", WARD),  # the title does not fit
        ("Give her the jug, Mr Lee", WARD),
        ("Give her the jug and him the pills - Mrs Khan", WARD),
        ("Give Bob (two) the cup", CELL),
        ("Bob ordered the cup for Carol", CELL),
        ("Carol, the apple is Bob's", CELL),
        ("Do me a favour and give me the cup", CELL),
        ("The plan is to give me the cup", CELL),
        ("Give Bob the cup, like I said, and the apple", CELL),
        ("A ruler for Sam", OFFICE),
        ("A pen for the box", OFFICE),
        ("Give Priya a lot of pens", OFFICE),
        ("Can I get the salt for me", KITCHEN),
        ("Can I get the salt", KITCHEN),
        ("Can I get the salt for the counter", KITCHEN),
        ("No worries, don't give Marco the knife", KITCHEN),
        ("Emma is wanting that you give me the white cup", LAB),
        ("Mr Lee is wanting that you give her the magazine", WARD),
        ("Now, where was I? Is the jug on the trolley?", WARD),
        # asked for one thing, given another (causes9): 'keeps asking for' is not rewritten
        ("Carol keeps asking for the apple, give her the cup", CELL),
    ],
)
def test_near_forms_of_the_new_classes_stay_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- stretches that are provably inert (the last step) ------------------------------------------
#
# The oracle: the plain request's reading; a stretch of interjections, praise, thanks, address,
# hurry or care between punctuation changes nothing. Any stretch with a word that could name,
# count, negate, delay, cancel, hedge or describe (or a noun the scene lacks) leaves it refused.

INERT = [
    "chop chop",
    "Righto",
    "Gotcha",
    "Okey dokey",
    "lovely jubbly",
    "snappy",
    "wonderful stuff",
    "careful now",
    "sharpish mate",
    "Splendid",
    "Kind regards",
    "hurry",
]
NOT_INERT = [
    "kidding",
    "spoon",
    "tonight",  # the lead's decision (session 20): a time that puts the task off is refused
    # (session 20, the lead's decision: a bare ', maybe' closing the whole request is a softener
    # like 'please' and is read: test_phrasing_s20.py; it is no longer listed here)
    "disregard",
    "twice",
    "full",
    "red",
    "upside down",
    "the other one",
    "forget it",
    "not yet",
    "spoon quickly",
]


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 5), st.sampled_from(INERT), st.booleans())
def test_inert_stretches_leave_the_request(scene: Scene, k: int, stretch: str, first: bool) -> None:
    request, want = plain_request(scene, k)
    text = f"{stretch}, {request}" if first else f"{request}, {stretch}"
    assert_means(text, want, scene)


@pytest.mark.parametrize("stretch", NOT_INERT)
@pytest.mark.parametrize("scene", [CELL, KITCHEN, WORKSHOP])
def test_stretches_that_could_mean_something_are_not_taken_off(stretch: str, scene: Scene) -> None:
    request, _ = plain_request(scene, 1)
    assert_refused(f"{request}, {stretch}", scene)


# -- wrong readings found by this session's fuzz (most already on main), now refused ---------------


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("You're Carol, bob wants a mug.", CELL),  # was: a mug each for Carol and Bob
        ("You're Alice, I need the bottle and the chips brought to Person B.", CELL),
        ("Give Alice the mug closest to her rather than the blue mug", CELL),
        ("Give Carol the chips, but don't give her the apple rather than the crisps", CELL),
        ("Bob wants a mug, the other one", CELL),  # was: both mugs
        ("Give Alice the cup, thanks, the other one", CELL),
        ("Give Bob the chips, he's hungry, just kidding", CELL),
        ("Hand Alice the bottle, she's got a meeting in five, tomorrow", CELL),
        ("Cup for Alice. Apple for Bob. That's all, maybe", CELL),
        ("You guys does Alice have the bottle?", CELL),  # a question after its hearers
        # ', twice' ending the request is not how often someone asked (found after blind13's
        # measurement; the measured grounder read the jug once)
        ("Mrs Khan keeps asking for water, could you get her the jug, twice", WARD),
        ("Marco was asking for the knife before, could you take it over to him, twice", KITCHEN),
        ("you guys is the apple on the shelf?", CELL),
    ],
)
def test_fuzz_findings_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


def test_fuzz_findings_keep_their_neighbours() -> None:
    # was: the two at once ('after thats it' lost its 'after')
    assert_means(
        "Give Person A the chips, and Person B gets the bottle after thats it",
        "chips>A ; bottle>B",
        CELL,
    )
    assert_means(
        "Give Person A the chips, and Person B gets the bottle after, thanks",
        "chips>A ; bottle>B",
        CELL,
    )
    assert_means("Give Alice the mug closest to her rather than the red mug", "mug_blue>A", CELL)
    assert_means("Give Bob the mug, the red one... no, the other one", "mug_blue>B", CELL)
    assert_means(
        "Give one mug to Alice, the other to Carol",
        "(mug_red>A & mug_blue>C) | (mug_blue>A & mug_red>C)",
        CELL,
    )
    assert_means("Give Bob the chips, he's hungry", "chips>B", CELL)
