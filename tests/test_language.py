"""The front end's lexicon, clause reader and mention accounting (rpg.schema.lexicon,
rpg.schema.clauses, rpg.schema.accounting). Language written by people is tested in
test_corpus.py; these pin down the mechanisms."""

import re

import numpy as np
import pytest

from rpg.domain.predicates import region_boxes
from rpg.errors import BadInput
from rpg.schema.builtin import Inexpressible, ParseError, normalize, parse
from rpg.schema.citations import uncited
from rpg.schema.feasibility import check_feasibility
from rpg.schema.meaning import matches, meaning


@pytest.mark.parametrize("text,expected", [
    ("Please carefully stack my blue block directly on the red block", ["stack(red,blue)"]),
    ("Construct a tower: three green blocks on top of the red block", ["stack(red,green,green,green)"]),
    ("Put the green block to the west of the yellow block", ["left_of(green,yellow)"]),
    ("put the red block to the north of the blue block", ["behind(red,blue)"]),
    ("In the SW corner build a stack of two blue blocks", ["stack(blue,blue)@front_left"]),
    ("bring the yellow block left of the red block", ["left_of(yellow,red)"]),
    ("put block 4 on block 2", ["stack(2,4)"]),
    ("Add one blue block under the red block. Then add 2 green blocks on top of the red block.",
     ["stack(blue,red,green,green)"]),
    ("Place a red block on the green block, a yellow block on the red and a blue one on the yellow.",
     ["stack(green,red,yellow,blue)"]),
    ("Place 2 blue blocks on top of the 2 red blocks.", ["stack(red,blue)", "stack(red,blue)"]),
    ("Place a column of two red blocks in each of the four corners.",
     ["stack(red,red)@back_left", "stack(red,red)@back_right", "stack(red,red)@front_left", "stack(red,red)@front_right"]),
    ("Place a row of 3 blue blocks on top of a row of 3 green blocks.", ["wall(green,green,green|blue,blue,blue)"]),
    ("slide left the blue block", ["in_region(blue,left)"]),
    ("move the green block to the center of the table", ["in_region(green,center)"]),
    ("place the green block in the middle", ["in_region(green,center)"]),
    ("put the red block at the back of the table", ["in_region(red,back)"]),
    # a structure placed relative to a cube: the structure's own clause, then the relation for each of its cubes
    ("Build a tower of 3 green blocks to the left of the red block",
     ["left_of(green,red)", "left_of(green,red)", "left_of(green,red)", "stack(green,green,green)"]),
    ("build a tower of three blocks to the left of the green block",
     ["left_of(blue,green)", "left_of(red,green)", "left_of(yellow,green)", "stack(red,blue,yellow)"]),
    ("put three blue blocks in a row in front of the yellow block",
     ["in_front_of(blue,yellow)", "in_front_of(blue,yellow)", "in_front_of(blue,yellow)", "line(blue,blue,blue)"]),
    # taking a cube off: rho_0 starts the stack, G is the top cube on the table (PlanBench's
    # "unstack ... from on top of ..." once compiled to the very stack it takes apart)
    ("unstack the blue block from on top of the red block", ["start:stack(red,blue)", "on_table(blue)"]),
    ("take the green block off the yellow block and put it on the table", ["start:stack(yellow,green)", "on_table(green)"]),
    ("build the tallest tower you can with 4 blocks", ["stack(red,blue,green,yellow)"]),
])
def test_reads(text, expected):
    assert meaning(parse(text)) == sorted(expected)


@pytest.mark.parametrize("text,named", [
    ("build one tower of red and one of green", "2 towers"),
    ("put three green blocks right of the red ones", "3 green"),
    ("a column of two in each corner", "each corner"),
    ("put red on blue and blue on red", "contradict"),
    ("push the red block until it is sitting on the target", "until"),
    # silent errors found by review: each compiled to a task that meant something else
    ("build a tower of three blocks to the left of the green block and stack them", "one green cube"),
    ("stack 3 red blocks and put 2 red blocks in a line", "line"),
    # a superlative structure with no count (SayCan's "make the highest block stack" compiled to
    # two cubes), and a cube taken off a stack the task does not start with
    ("make the highest block stack.", "as many cubes as there are"),
    ("build the tallest tower you can", "no count"),
    ("stack the blocks as high as you can", "as high as you can"),
    ("unstack the red block and put it left of the blue block", "'unstack' takes a cube off a stack"),
])
def test_refuses_naming_what_it_could_not_place(text, named):
    with pytest.raises(ParseError, match=named):
        parse(text)


def test_a_real_word_is_not_corrected_into_another():
    words = normalize("bring the red block next to the blue block")[0].split()
    assert "ring" not in words and words[0] == "place"  # a placement verb, not the ring structure
    assert normalize("stack teh red block on the blue block")[0].startswith("stack the red")
    assert normalize("Built a tower")[0] == "build a tower"


def test_relation_words_must_be_in_the_task():
    from rpg.schema.accounting import UnaccountedMention, account
    from rpg.schema.lexicon import COLOR_RE
    from rpg.schema.reading import canon_color

    schema = parse("stack the red block on the blue block")
    with pytest.raises(UnaccountedMention, match="left of"):
        account("stack the red block on the blue block left of the green block", schema, COLOR_RE, canon_color)
    record = account("put the red block left of the blue block", parse("put the red block left of the blue block"),
                     COLOR_RE, canon_color)
    assert {"mention": "left of", "kind": "relation", "consumed_by": "left_of"} in record


def test_a_group_named_on_its_own_is_not_read_as_a_tower():
    """"Two red blocks in the corner" says where, not that they stand on each other."""
    assert meaning(parse("place two red blocks in the back left corner of the table")) == [
        "in_region(red,back_left)", "in_region(red,back_left)"]
    assert meaning(parse("place a stack of two red blocks in the back left corner")) == ["stack(red,red)@back_left"]


def test_the_accounting_record_says_which_words_produced_which_part():
    from rpg.schema.builtin import check_mentions

    schema = parse("Put three green blocks in a row to the left of the red block")
    record = {(r["kind"], r["mention"]): r["consumed_by"] for r in check_mentions(schema.instruction, schema)}
    assert record[("color", "green")].count("green") == 3 and record[("color", "red")] == "red"
    assert record[("structure", "row")] == "in_line"
    assert ("relation", "to the left of") in record and ("count", "3 green blocks") in record


@pytest.mark.parametrize("text,kind,word", [
    ("Do not put the red block on the blue block", "negation", "not"),
    ("Don't stack the green block on the red block", "negation", "don't"),
    ("Build a tower without the yellow block", "negation", "without"),
    ("If the red block is on the table, stack it on the blue block", "condition", "if"),
    ("Put the big block on the small block", "size", "big block"),
    ("Place the red ball on the blue block", "object", "ball"),
    ("Put the red block 10 cm to the left of the blue block", "quantity", "10 cm"),
    ("Stack the red block on the blue block for 5 seconds", "time", "5 seconds"),
    # an order nobody defined, or an earlier action: these compiled, dropping the reference
    ("put the second block on the first block", "reference", "the second block"),
    ("Build a tower of 3 blocks, the first block is red", "reference", "the first block"),
    ("Line up three cubes; the second cube should be blue", "reference", "the second cube"),
    ("put the block you just moved on the red one", "reference", "you just moved"),
    # a pronoun with nothing named before it to refer to (these compiled two default cubes)
    ("stack them", "reference", "them"),
    ("put them in a row", "reference", "them"),
    ("unstack that.", "reference", "that"),
    ("put the blue block back in its original position", "reference", "original"),
    # a cube picked by where it stands now, or by what was shown (these compiled)
    ("move the block on the left onto the block on the right", "reference", "the block on the left"),
    ("put the blocks in the order shown", "reference", "shown"),
    ("place the same block on the green patch", "reference", "the same block"),
    ("move the red block to the blue block's position", "reference", "block's position"),
    # a cube picked by its place in a scene nobody described (these compiled a red cube for it)
    ("Stack the top block on the green one.", "reference", "the top block"),
    ("Put the nearest cube on the red cube.", "reference", "the nearest cube"),
    ("Put the rightmost block on the red block.", "reference", "the right block"),
    ("Put the block that is closest to you on the blue block.", "reference", "closest to you"),
    ("Stack the blocks in the same order.", "reference", "the same order"),
    ("Put the blue block where the red block was.", "reference", "where the red block was"),
    # a question is no instruction (these compiled the relation asked about)
    ("which block is on top of the blue block?", "question", "which block is on top of the blue block?"),
    ("is the red block left of the green block?", "question", "is the red block left of the green block?"),
    # an unknown noun heading an object's phrase, an unknown command verb
    ("Pick up a nut and place it onto a peg.", "object", "nut"),
    ("Sweep a puck off the table.", "object", "puck"),
    ("throw the red block", "action", "throw"),
    ("One robot stacks the green cube while the other holds the blue cube", "time", "while"),
])
def test_meaning_the_domain_lacks_is_refused_naming_the_word_and_why(text, kind, word):
    from rpg.schema.builtin import Inexpressible

    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert any(k == kind and word in words for k, words, _ in exc.value.reasons), exc.value.reasons
    assert f"'{word}'" in str(exc.value)


@pytest.mark.parametrize("text,reasons", [
    # every class the text says is named, the first in full and the rest in short
    ("Rotate a dial 180 degrees.", {"action": "180 degrees", "object": "dial"}),  # a rotation by an angle
    ("Pull a lever down 90 degrees.", {"quantity": "degrees", "object": "lever"}),
    ("Sweep a puck off the table.", {"action": "off the table", "object": "puck"}),
    ("Can you tell me how many blue blocks there are?", {"question": "tell me how", "quantity": "many"}),
    # a swap puts each cube where the other stands now: the current scene
    ("Swap positions of the red cube and the yellow cube", {"reference": "swap"}),
    ("switch the places of the red and blue blocks", {"reference": "switch the places"}),
    ("push the red cube off the table", {"action": "off the table"}),
    # "I" before a verb is the speaker, not a letter cube's label
    ("place the block I pointed at on the green patch", {"reference": "block i pointed"}),
    # a colour's name outside the palette, where a cube's colour stands
    ("Put the mauve cube on the red cube", {"colour": "mauve"}),
    ("stack the crimson block on the blue patch", {"colour": "crimson"}),
])
def test_every_reason_the_domain_lacks_is_named(text, reasons):
    with pytest.raises(Inexpressible) as exc:
        parse(text)
    got = {k: words for k, words, _ in exc.value.reasons}
    assert {k: w for k, w in reasons.items() if w in got.get(k, [])} == reasons, exc.value.reasons
    message = str(exc.value)
    assert message.count("Rephrase") == 1 and "\n" not in message
    assert all(f"'{w}'" in message for w in reasons.values())


@pytest.mark.parametrize("text,kind,word", [
    # a motion or a pose off the table is an action (these were refused as unknown words, "air" as an object,
    # and "hold ... above the red patch" compiled a cube on the patch)
    ("Flip the A cube upside down.", "action", "upside down"),
    ("Slide the orange cube back and forth across the table.", "action", "back and forth"),
    ("Hold the blue cube above the red patch.", "action", "hold the blue cube above"),
    ("Lift the orange block up and hold it in the air.", "action", "in the air"),
    ("Hold the blue cube in the air above the red cube.", "action", "in the air"),
    ("Push the tower over.", "action", "push the tower over"),
    ("Slide the green cube across the table without lifting it.", "action", "without lifting"),
    # only the robot moves: no goal for the cubes
    ("Move the gripper back to its home pose.", "no_goal", "home pose"),
    ("hover above the green patch for a moment, then stop.", "no_goal", "hover"),
    # a message that asks nothing of the cubes
    ("Just look at the blocks for a moment.", "no_goal", "look"),
    ("Hi robot, good morning!", "no_goal", "hi"),
    ("Thanks, that's all for today.", "no_goal", "thanks"),
    # a measured distance, a colour outside the palette by its role or its list
    ("Place the cyan cube about a hand's width from the white cube.", "quantity", "hand's width"),
    ("Push the red cube as far to the right as possible.", "quantity", "as far to the right as possible"),
    ("Build a tower: maroon at the bottom, olive on top.", "colour", "maroon"),
    ("stack red, teal and blue", "colour", "teal"),
    ("Stack the turquoise cube on the red one.", "colour", "turquoise"),  # not cyan: another colour
])
def test_a_must_refuse_text_is_refused_for_its_class(text, kind, word):
    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert exc.value.reasons[0][0] == kind and word in exc.value.reasons[0][1], exc.value.reasons


@pytest.mark.parametrize("text,expected", [
    ("hi, red on blue thanks", ["stack(blue,red)"]),  # a greeting around a goal is no reason to refuse
    ("push the red block over the blue patch", ["on_patch(red,patch:blue)"]),  # "over" a patch is a place
    ("put the red block over the blue block", ["stack(blue,red)"]),
])
def test_words_near_the_new_refusals_still_compile(text, expected):
    assert meaning(parse(text)) == expected


def test_a_capital_i_before_a_noun_is_still_a_letter_cube():
    assert meaning(parse("put block I on block J")) == ["stack(J,I)"]


@pytest.mark.parametrize("text,expected", [
    ("Stack the red brick on the blue brick", ["stack(blue,red)"]),
    ("We'll need a tower of three blue blocks.", ["stack(blue,blue,blue)"]),
    ("Let's stack the red block on the blue one.", ["stack(blue,red)"]),
    ("Maybe put the red block on top of the blue block, that would be nice", ["stack(blue,red)"]),
    ("I need the green block on the yellow block", ["stack(yellow,green)"]),
    ("Put the green block anywhere on the left side of the table", ["in_region(green,left)"]),
    ("Move the red cube to the back leftmost corner", ["in_region(red,back_left)"]),
    ("Put one block on top of the other one", meaning(parse("Stack two blocks on top of each other."))),
])
def test_harmless_words_and_curated_synonyms_are_read(text, expected):
    assert meaning(parse(text)) == expected


def test_a_corner_needs_both_of_its_sides():
    with pytest.raises(ParseError, match="names no one corner"):
        parse("Move the red cube to the right corner")


@pytest.mark.parametrize("text,expected", [
    # a count or colour before the structure noun is the whole structure's
    ("build a four-high white stack", ["stack(white,white,white,white)"]),
    ("Make a 3 block tall cyan tower", ["stack(cyan,cyan,cyan)"]),
    ("build a blue tower of 3 blocks", ["stack(blue,blue,blue)"]),
    ("build a four-story white tower", ["stack(white,white,white,white)"]),
    # a count right after "of" and before a comma (a pyramid of six with invented colours had been built)
    ("Make a pyramid of three, two black on the bottom and a white one on top, in the front left corner.",
     ["pyramid(black,black|white)@front_left"]),
    # a colour listed twice in a sequence with roles keeps both cubes (one blue had been dropped)
    ("A tower of four: red base, then blue, then red, then blue on top.", ["stack(red,blue,red,blue)"]),
    # the middle cube at the tower's middle with the top said (green had gone to the bottom), and a role after a
    # comma (it had been read as the table's centre, with a fourth cube)
    ("stack red, green and blue with green in the middle and red on top", ["stack(blue,green,red)"]),
    ("stack the red, green and blue blocks, green in the middle", ["stack(red,green,blue)"]),
    # an alternating tower's named end (red had stayed at the bottom)
    ("a tower of four alternating red and blue, blue at the bottom", ["stack(blue,red,blue,red)"]),
    ("a tower of four alternating red and blue, red on top", ["stack(blue,red,blue,red)"]),
    # the colour said before the height, after "of" without a noun, or "every cube red" (each had reached one cube)
    ("build a green 3-high tower", ["stack(green,green,green)"]),
    ("build a 3 block high tower of green", ["stack(green,green,green)"]),
    ("build a tower, four cubes high, every cube red", ["stack(red,red,red,red)"]),
    ("build a tower 3 high, green", ["stack(green,green,green)"]),
    ("build two 3-high towers of green blocks", ["stack(green,green,green)", "stack(green,green,green)"]),
    ("build a 4-wide wall of red blocks, 2 high", ["wall(red,red,red,red,red,red,red,red)"]),  # it had been 3 wide
    # a tower's "blue top" is its top cube (blue had been put at the bottom)
    ("build a tower of four blocks with a blue top", ["stack(red,green,yellow,blue)"]),
    ("build a pyramid of six blocks with a red base", ["pyramid(red,red,red|blue,green|yellow)"]),  # a layer
    # ... and a colour said after it (one cube of it and three defaults had been built)
    ("Build a 4-high tower of yellow blocks.", ["stack(yellow,yellow,yellow,yellow)"]),
    ("I need a tower, 3 blocks high, all green.", ["stack(green,green,green)"]),
    # a group after "one of" is one tower's
    ("one tower of two pink and one of two brown", ["stack(brown,brown)", "stack(pink,pink)"]),
    ("make two towers: one of two pink blocks and one of two brown blocks", ["stack(brown,brown)", "stack(pink,pink)"]),
    # towers counted, then each said after "please:" or a comma (both had become white on black)
    ("Two stacks please: white on black, and black on white.", ["stack(black,white)", "stack(white,black)"]),
    ("make two stacks, white on black and black on white", ["stack(black,white)", "stack(white,black)"]),
    # a role binds to its end of the tower
    ("a tower of four where the top one is white", ["stack(red,blue,green,white)"]),
    ("build a tower of four blocks, the bottom block is black", ["stack(black,red,blue,green)"]),
    # a place named alone is kept
    ("build a four-high white stack right in the middle", ["stack(white,white,white,white)@center"]),
])
def test_structure_phrases_keep_their_count_colour_role_and_place(text, expected):
    assert meaning(parse(text)) == expected


def test_a_pair_next_to_each_other_at_a_side_has_both_cubes_there():
    # (it was refused, not dropped; "make a row of three red blocks on the left" is read too:
    # test_a_wide_structure_in_a_place_has_every_cube_there)
    assert sorted(meaning(parse("put two black cubes next to each other at the front"))) == [
        "in_region(black,front)", "in_region(black,front)", "next_to(black,black)"]


@pytest.mark.parametrize("text", ["line up the pink cubes, then the brown ones",
                                  "put the red cubes in a row and the blue cubes in another row"])
def test_a_plural_colour_group_is_not_read_as_one_cube(text):
    """Issue 30 class 3: these compiled to one pink and one brown cube in an unordered line."""
    with pytest.raises(ParseError, match="names several"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("stack the blue blocks", ["stack(blue,blue)"]),
    ("group the same colored blocks together", None),  # "the same" is not a reference
    ("put the red and blue blocks in a line", ["line(blue,red)"]),  # a listed plural: one of each
])
def test_plural_groups_that_are_read(text, expected):
    schema = parse(text)
    if expected is not None:
        assert meaning(schema) == expected


@pytest.mark.parametrize("text,expected", [
    # counted colour groups said together keep each group's count (issue 30 item 4)
    ("Put 2 red blocks and 2 blue blocks in a row.", ["line(blue,blue,red,red)"]),
    # with "the" before each group (it had been refused: the second group's count was lost)
    ("Put the two yellow cubes and the two black cubes in a row, any order.", ["line(black,black,yellow,yellow)"]),
    ("Put the two yellow cubes and the black cube in a row.", ["line(black,yellow,yellow)"]),
    ("Make a line of 3 red and 2 blue blocks", ["line(blue,blue,red,red,red)"]),
    ("Put 3 red and 3 blue blocks in a circle.", ["circle(blue,blue,blue,red,red,red)"]),
    ("Make a 2 by 2 grid of 2 red and 2 blue blocks", ["grid(2x2:blue,blue,red,red)"]),
    # a listed colour is one cube: a circle of the red, green and blue blocks has three
    ("Arrange the red, green and blue blocks in a circle.", ["circle(blue,green,red)"]),
])
def test_counted_groups_and_lists_keep_their_counts(text, expected):
    assert meaning(parse(text)) == expected


def test_a_circle_of_two_listed_cubes_is_refused_not_padded():
    with pytest.raises(ParseError, match="a circle needs at least 3 cubes and it names 2"):
        parse("Arrange the red and blue blocks in a circle.")


@pytest.mark.parametrize("text,expected", [
    ("Pick the red block and place it on the left side.", ["in_region(red,left)"]),
    ("Pick the yellow block and place it on the middle.", ["in_region(yellow,center)"]),
    ("push the yellow block towards the green block", ["next_to(green,yellow)"]),
    ("move the blue block to the red block", ["next_to(blue,red)"]),
    ("put the red block on a goal patch", ["on_patch(red,patch:gray)"]),
    # "after you put": a sequence, not a reference to an earlier action
    ("put the red block next to the blue block after you put the green block on the yellow block",
     meaning(parse("put the green block on the yellow block, then put the red block next to the blue block"))),
])
def test_places_and_approaches_of_the_grown_development_split(text, expected):
    assert meaning(parse(text)) == expected


def test_a_patch_of_no_colour_must_be_in_the_task():
    """"stack two cubes at a target position" compiled to a stack with no patch (silently wrong);
    now "at a target position" is read as the goal patch the stack stands on."""
    schema = parse("the robot has to stack two cubes at a target position")
    assert [a.kind for a in schema.assets].count("goal_patch") == 1
    assert any(p.name in ("on_patch", "stack_on_patch") for p in schema.goal_predicate().conjuncts())



def test_readers_register_themselves_in_one_order_and_layers_import_downwards():
    """Every reader is in the registry at its own order; the lower layers of the front end
    (lexicon, reading, accounting) load without the readers or the public face."""
    import subprocess
    import sys

    from rpg.schema.readers.registry import READERS, ordered, reader

    orders = [r.order for r in ordered()]
    assert len(READERS) >= 20 and len(set(orders)) == len(orders) and orders == sorted(orders)
    assert [r.name for r in ordered()[-2:]] == ["recognize_relational", "recognize_independent_parts"]  # general ones last
    with pytest.raises(ValueError, match="has that order"):
        reader(order=ordered()[0].order)(lambda f, b: False)
    probe = ("import sys, rpg.schema.accounting, rpg.schema.reading, rpg.schema.lexicon; "
             "print(sorted(m for m in sys.modules if m.startswith(('rpg.schema.readers', 'rpg.schema.builtin'))))")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_relation_words_are_declared_on_their_predicates():
    """The relational reader's words for a relation are the ones its predicate class declares,
    and what they say is that predicate ("beside" -> next_to)."""
    from rpg.domain.predicates import PREDICATES
    from rpg.schema.lexicon import PAIRWISE_RELATIONS, REL_PATTERNS

    declared = dict((name, pattern) for pattern, name in REL_PATTERNS if name in PAIRWISE_RELATIONS)
    assert declared == {name: PREDICATES[name].phrases for name in PAIRWISE_RELATIONS}
    for name in PAIRWISE_RELATIONS:
        phrase = PREDICATES[name].phrase
        schema = parse(f"put the red block {phrase} the blue block")
        assert [p.name for p in schema.goal_predicate().conjuncts() if len(p.object_names()) == 2] == [name], phrase


@pytest.mark.parametrize("text", [
    "Build a tower and put the red block behind it",  # "it": the tower
    "stack two blocks and put the red block next to them",
    "Pick up the red block and put it on the blue block",
    "The goal is to pick up a red cube and stack it on top of a green cube",
])
def test_a_pronoun_with_something_named_before_it_is_read(text):
    parse(text)


def test_an_unknown_word_that_is_no_object_or_command_is_only_named():
    """A modifier or an abstract noun is not refused as a missing object or action: the
    refusal names the word and says the parser could not read it."""
    for text, word in (("stack the shiny blocks", "shiny"), ("stack the blocks roughly", "roughly")):
        with pytest.raises(ParseError, match=rf"could not parse .*'{word}'") as exc:
            parse(text)
        assert not hasattr(exc.value, "kind")
    with pytest.raises(ParseError):  # "think" is ignored (issue 30, item 3); the sort still has no order
        parse("sort the blocks in the way you think it best fits")


@pytest.mark.parametrize("text,verb", [("pick up the orange block", "pick up"), ("grab the red cube", "grab"),
                                       ("lift the blue block and hold it", "lift")])
def test_an_action_with_nowhere_for_the_cube_to_end_says_no_end_state(text, verb):
    with pytest.raises(ParseError, match=rf"says no end state: '{verb}' is an action"):
        parse(text)


def test_framing_around_the_task_is_dropped():
    assert meaning(parse("A simple task where the objective is to put the red block on the blue block.")) == \
        meaning(parse("put the red block on the blue block"))


@pytest.mark.parametrize("text", ["Push the block to a patch.", "the robot has to push a cube to a target position",
                                  "slide the block to target", "Pick and place a block to a patch."])
def test_a_cube_moved_to_a_patch_ends_on_it(text):
    assert meaning(parse(text)) == meaning(parse("put a block on the goal patch"))


def test_a_request_phrased_as_a_question_is_an_instruction():
    """"can you ...?" asks for an arrangement: it compiles (a question about the scene does not)."""
    assert parse("Can you put the red block on the blue block?").goal.name == "stack"
    assert parse("could you stack the red block on the blue block?").goal.name == "stack"


def test_sorting_says_no_line_unless_a_line_or_an_order_is_said():
    """"sort the blocks" compiled a line of four colours (a structure nobody named); "by
    colour" sorts like with like (piles), and a line needs a line word or an order to read."""
    for text in ("sort the blocks", "arrange the blocks by color", "organize the blocks by color",
                 "sort the blocks from left to right by color"):
        with pytest.raises(BadInput):
            parse(text)
    for text in ("sort the blocks by colour", "organize the blocks into piles by color"):
        assert parse(text).goal.name == "piles", text
    assert parse("arrange the blocks in a row").goal.name == "in_line"


@pytest.mark.parametrize("text, want", [
    # a count said in another form ("a circle of five", "two rows of four") is the count
    ("arange the blocks in a circle of five", "circle(red,red,red,red,red)"),
    ("make a wall of red bricks, two rows of four", "wall(red,red,red,red,red,red,red,red)"),
    # the colours listed are the line's, in the rainbow's own order, read from either end
    ("Line up the red, orange, yellow, green blocks in rainbow order", "line[sequence](red,orange,yellow,green)"),
    ("line up five blocks from left to right in rainbow order", "line[left_to_right](red,orange,yellow,green,blue)"),
    # cubes listed with their nouns keep the order said ("first, then")
    ("put the blue block first, then the red block, then the green block, in a row from left to right",
     "line[left_to_right](blue,red,green)"),
    ("put the red block, the blue block and the green block in a row from left to right",
     "line[left_to_right](red,blue,green)"),
    ("build a column of red, blue and green from front to back", "line[front_to_back](red,blue,green)"),
    # a layer named without a verb keeps its colour to that layer, not the whole pyramid
    ("make a pyramid of six cubes with the three on the bottom being red", "pyramid(red,red,red|?,?|?)"),
    ("make a pyramid of six cubes with the bottom row red", "pyramid(red,red,red|?,?|?)"),
    ("build a pyramid of six blocks, the bottom three red and the top yellow", "pyramid(red,red,red|?,?|yellow)"),
    # "reverse order" does not flip the ends the text names
    ("Stack the blocks in reverse order: blue at the bottom, then green, then red on top", "stack(blue,green,red)"),
])
def test_counts_and_orders_said_another_way(text, want):
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))


@pytest.mark.parametrize("text", ["put half of the cubes in a line", "stack as many blocks as you can",
                                  "put several cubes on the white patch", "build the tower as high as possible",
                                  "Place some white cubes next to the black cube.", "stack some of the blocks"])
def test_a_vague_quantity_is_refused(text):
    from rpg.schema.builtin import Inexpressible

    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert exc.value.kind == "quantity"


def test_an_unnamed_tower_in_a_place_is_free_and_a_comma_role_is_kept():
    assert parse("build a three-block tower in the center of the table").goal.children()[0].name == "unordered_stack"
    goal = parse("please make a tower out of a red, a blue and a green block, red at the bottom").goal
    assert goal.name == "anchored_stack" and goal.bottom and not goal.top


@pytest.mark.parametrize("text", [
    "put the red block to the left of the blue block and to the right of the blue block",
    "put the red block on the left of the blue block and the blue block on the left of the red block",
    "put red left of blue, blue left of green and green left of red",
])
def test_directional_relations_no_placement_satisfies_are_refused_as_a_contradiction(text):
    with pytest.raises(ParseError, match="contradict"):
        parse(text)


def test_relations_on_different_pairs_still_compile():
    assert len(parse("put the red block left of the blue block and the green block right of the blue block")
               .goal.children()) >= 2


def test_to_its_left_is_a_relation_to_the_cube_named_before():
    """"also to its left" was dropped silently (G held only "behind"); it reads as "to the left of it", which with
    "behind" puts the blue cube diagonally behind and left of the red one (both relations kept)."""
    assert sorted(meaning(parse("place the blue block behind the red one and also to its left"))) == [
        "behind(blue,red)", "left_of(blue,red)"]


def test_a_column_along_the_table_is_a_line_on_that_axis():
    goal = parse("make a column of three green cubes going from front to back").goal
    assert goal.name == "in_line" and goal.axis == "x"
    assert parse("make a column of three green cubes").goal.name != "in_line"


def test_a_line_sorted_by_colour_names_no_order_and_is_refused():
    """"sorted by color" in a line was dropped silently: the line was free."""
    for text in ("line up the blocks from left to right sorted by color", "put the blocks in a row ordered by colour"):
        with pytest.raises(ParseError, match="sorted by colour"):
            parse(text)


def test_the_other_block_needs_a_cube_set_apart_before_it():
    from rpg.schema.builtin import Inexpressible

    with pytest.raises(Inexpressible, match="'the other block'") as exc:
        parse("put the other block on the green patch")
    assert exc.value.kind == "reference"
    # "the other one" after "one red block" is a second red cube: it had compiled one red cube on both patches;
    # now refused (one cube on two patches); reading it as two cubes is still to do
    try:
        goal = parse("put one red block on the green patch and the other one on the blue patch").goal_predicate()
        assert len({p.a for p in goal.children()}) == 2
    except ParseError as exc:
        assert "two goal patches" in str(exc)


def test_a_colour_counted_alone_bounds_its_cubes():
    """"the top blue block on two red ones" compiled a pyramid of five red cubes; a colour named
    only in counts may have no more cubes than they add up to, unless a word multiplies them."""
    with pytest.raises(ParseError, match="names 2 red cubes but the task read has 5"):
        parse("make a pyramid with the top blue block on two red ones")
    assert len(parse("Place a column of three orange blocks in all four corners.").assets) == 12


@pytest.mark.parametrize("text, want", [
    ("put two stacks of two blocks in the front left and front right corners",
     "stack(?,?)@front_left; stack(?,?)@front_right"),
    ("build a stack of two blocks in the front left corner and another in the front right corner",
     "stack(?,?)@front_left; stack(?,?)@front_right"),
    ("put a stack of two blocks in each of the front left and front right corners",
     "stack(?,?)@front_left; stack(?,?)@front_right"),
    ("put a red tower of two blocks in the back left corner and another in the front right corner",
     "stack(red,red)@back_left; stack(red,red)@front_right"),
    ("build a tower of three blocks in the back left corner and a tower of two blocks in the front right corner",
     "stack(?,?,?)@back_left; stack(?,?)@front_right"),
])
def test_structures_each_in_their_own_place(text, want):
    """Each part is read on its own and its base put in its place. These dropped a place, or put one cube in two
    corners."""
    from rpg.schema.meaning import matches

    schema = parse(text)
    assert matches(want, meaning(schema)), meaning(schema)
    # the parts' open colours are one colour: any cube may stand in either stack (two colours nobody said had each
    # been demanded in one corner, a goal stricter than the words)
    assert len({a.color for a in schema.assets}) == 1 or "red" in text


def test_one_stack_in_two_places_is_refused_not_read_as_one_cube_in_both():
    with pytest.raises(ParseError, match="which do not meet"):
        parse("put a stack of two blocks in the front left and front right corners")
    with pytest.raises(ParseError, match="which do not meet"):
        parse("put the red block in the front left corner and in the back right corner")


@pytest.mark.parametrize("text, want", [
    ("I want two stacks: white on black, and black on white", "stack(black,white); stack(white,black)"),
    ("make two stacks: red on blue and green on yellow", "stack(blue,red); stack(yellow,green)"),
    ("build 3 towers: red on blue, green on yellow, and a stack of two white blocks",
     "stack(blue,red); stack(yellow,green); stack(white,white)"),
])
def test_towers_counted_then_each_described(text, want):
    """"two stacks: white on black, and black on white" gave two stacks white under black."""
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))
    goal = parse(text).goal
    assert all(p.name == "stack" for p in goal.children())  # each order said is kept


def test_a_sort_spelled_out_after_a_colon_is_its_details():
    """The heading's "the patches" invented a gray patch with a red and a blue cube on it."""
    schema = parse("Sort the cubes onto the patches by colour: red cubes on the red patch, blue cubes on the blue patch")
    assert sorted(a.color for a in schema.assets if a.kind == "goal_patch") == ["blue", "red"]
    colors = {a.name: a.color for a in schema.assets}
    assert all(colors[p.a] == colors[p.patch] for p in schema.goal.children())


def test_a_matching_patch_is_the_cube_s_own_colour_and_adds_no_cube():
    """"put the red block on its matching patch" added a blue cube and patch nobody named;
    "stack the red blocks on the patch of the same color" put them on a gray patch."""
    schema = parse("put the red block on its matching patch")
    assert sorted(a.name for a in schema.assets) == ["red", "red_patch"]
    with pytest.raises(ParseError, match="patch of its own colour"):
        parse("stack the red blocks on the patch of the same color")


@pytest.mark.parametrize("text, word", [("stack the blocks in this arrangement", "this arrangement"),
                                        ("put the red block on the blue block like in the picture", "picture"),
                                        ("put the red block on the blue block as shown", "as shown")])
def test_what_is_shown_or_seen_is_refused_as_a_reference(text, word):
    from rpg.schema.builtin import Inexpressible

    with pytest.raises(Inexpressible, match=f"'{word}' refers to something shown or seen") as exc:
        parse(text)
    assert exc.value.kind == "reference"


@pytest.mark.parametrize("text, want", [
    ("use the gripper to put the red block on the blue block", "stack(blue,red)"),
    ("Use the left arm to pick up the red block and place it in the center of the table", "in_region(red,center)"),
    ("put the red block on the left with the right arm", "in_region(red,left)"),
    ("A collaborative task where two robot arms need to work together to stack two cubes.", "stack(?,?)"),
])
def test_which_arm_or_hand_moves_the_cubes_says_nothing_of_the_goal(text, want):
    """Refused over 'arm', 'gripper' or 'hand' before; the effector's side is not a place."""
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))


@pytest.mark.parametrize("text, want", [
    ("put the red and green blocks next to the blue block", "next_to(blue,green); next_to(blue,red)"),
    ("put the red block to the left of the blue and green blocks", "left_of(red,blue); left_of(red,green)"),
    ("put the red block next to the blue block and the green block", "next_to(blue,red); next_to(green,red)"),
    ("put the red block between the blue and green blocks", "between(red;blue,green)"),
])
def test_a_relation_said_once_of_two_cubes_holds_for_each(text, want):
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))


@pytest.mark.parametrize("text, want", [
    ("place the yellow block in the top left corner", "in_region(yellow,back_left)"),
    ("put the red block at the bottom right corner", "in_region(red,front_right)"),
    ("move the blue cube to the far right", "in_region(blue,right)"),
    ("put the green block near the front edge", "in_region(green,front)"),
    ("stack the red block on the blue block near the back edge", "stack(blue,red)@back"),
    # refused before ("the front edge" had no place); each cube of the pair now stands there
    ("two black cubes side by side near the front edge",
     "in_region(black,front); in_region(black,front); next_to(black,black)"),
])
def test_places_said_as_on_a_map_or_by_an_edge(text, want):
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))


def test_a_tower_reversed_starts_built_and_ends_upside_down():
    """"Reverse the tower" compiled a fresh tower in any order ("reverse" was dropped)."""
    schema = parse("Reverse the tower")
    start = schema.initial_state.structures[0]
    assert schema.goal.name == "stack" and list(schema.goal.objects) == start[::-1]
    assert len(parse("invert the stack of 4 blocks").goal.objects) == 4
    with pytest.raises(ParseError, match="turns over a tower it does not describe"):
        parse("reverse the red tower")


def test_a_role_said_as_a_clause_is_the_listed_cube_s_role():
    """"where the yellow one is at the top" added a second yellow cube on top."""
    goal = parse("Build a stack of the red, blue and yellow blocks where the yellow one is at the top").goal
    assert goal.name == "anchored_stack" and goal.top and len(goal.objects) == 3


@pytest.mark.parametrize("text", ["Place the blue block on top of the stack", "put the red block next to the tower",
                                  "put the red block on the stack of blue blocks"])
def test_a_structure_nobody_described_is_not_invented(text):
    """These compiled a two-cube tower of colours nobody named for "the stack" to stand for."""
    with pytest.raises(ParseError, match="refers to a (?:stack|tower)|not described cube by cube"):
        parse(text)


@pytest.mark.parametrize("text, want", [
    ("stack the red block on the blue block, then put the green block on the stack", "stack(blue,red,green)"),
    ("put the red block on the blue block, then the green block on top of the tower", "stack(blue,red,green)"),
    ("build a tower of the red and blue blocks and put the green block behind the tower", "behind(green,red); stack(red,blue)"),
    # a cube next to a listed tower: "next to" is judged against the tower's bottom cube, so the order read is kept
    ("build a tower of red and blue blocks and put the green block next to the tower", "next_to(green,red); stack(red,blue)"),
])
def test_the_stack_built_before_is_the_one_referred_to(text, want):
    """"... then put the green block on the stack" put green between blue and red."""
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))
    with pytest.raises(ParseError):  # on red (the top) or between the two? not said
        parse("put the red block on the blue block, then put the green block on it")


@pytest.mark.parametrize("text, want", [
    ("Build a tower and put the red block behind it", "behind(red,?); stack(?,?)"),
    ("stack two blocks and put the red block next to them", "next_to(?,red); stack(?,?)"),
])
def test_a_cube_put_beside_a_tower_is_not_also_in_a_second_tower(text, want):
    """These gave the red cube a stack of its own too (stack(red,blue)) besides the tower it
    stands beside."""
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))


@pytest.mark.parametrize("text", [
    "Build a tower of three blocks and make the top block red.",
    "Build a tower of three blocks; the top block should be red.",
    "Build a tower of three blocks. The top one is red.",
    "Build a tower of three blocks, and make sure the top block is red.",
])
def test_the_top_cube_s_colour_said_after_the_tower_is_its_role(text):
    """These compiled a tower with the red cube anywhere (the role was lost)."""
    goal = parse(text).goal
    assert goal.name == "anchored_stack" and len(goal.objects) == 3
    assert goal.top and goal.objects[-1].startswith("red") and not goal.bottom


def test_a_named_cube_the_goal_leaves_where_it_falls_has_no_place():
    """"... with a green block on top" of a stack whose cubes are all named compiled the stack
    and a green cube nothing placed."""
    with pytest.raises(ParseError, match="green cube.s. it names have no place"):
        parse("Stack the red block on the blue block with a green block on top.")


@pytest.mark.parametrize("text, want", [
    ("Put two green cubes on the left.", "in_region(green,left); in_region(green,left)"),
    ("Put the red and blue blocks on the left.", "in_region(blue,left); in_region(red,left)"),
    ("Stack the red block on the blue block on the right.", "stack(blue,red)@right"),
    ("Build a tower of three blocks on the right.", "stack(?,?,?)@right"),
    ("Put the yellow cube in the top right.", "in_region(yellow,back_right)"),
    ("Move the red block to the upper left.", "in_region(red,back_left)"),
    ("Place the green block on the lower left.", "in_region(green,front_left)"),
])
def test_a_bare_side_ending_a_text_with_nothing_else_to_anchor_it_is_the_table_s(text, want):
    """These were refused ("could not find a task", 'upper' unknown)."""
    from rpg.schema.meaning import matches

    assert matches(want, meaning(parse(text))), meaning(parse(text))


@pytest.mark.parametrize("text", ["Put the red block next to the blue block on the left.",
                                  "Put the red block on the blue block and the green block on the left."])
def test_a_bare_side_with_something_it_could_be_the_side_of_stays_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_a_diagonal_of_a_cube_is_refused_not_read_as_one_relation():
    """"to the top left of the blue block" compiled left_of(red, blue), dropping "top"."""
    with pytest.raises(ParseError, match="diagonal"):
        parse("Move the red block to the top left of the blue block.")
    assert meaning(parse("Put the red block in the front left of the table.")) == ["in_region(red,front_left)"]


@pytest.mark.parametrize("text, kind, word", [
    ("Put the enormous block on the red block.", "size", "enormous"),
    ("Stack the red block on the blue block, then topple it.", "action", "topple"),
    ("Make a stack of a dozen blocks.", "quantity", "dozen"),
])
def test_an_unknown_word_close_to_meaning_the_domain_lacks_is_refused_for_that(text, kind, word):
    """These were refused only as unknown words ("could not parse 'enormous'")."""
    from rpg.schema.builtin import Inexpressible

    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert exc.value.kind == kind and f"'{word}'" in str(exc.value)


def test_an_unknown_adverb_close_to_an_ignorable_word_is_dropped_and_listed():
    """"Swiftly" was refused as an unknown word; it reads like "quickly" and is dropped, and the
    accounting record says so."""
    from rpg.schema.builtin import check_mentions

    schema = parse("Swiftly stack the red block on the blue block.")
    assert meaning(schema) == ["stack(blue,red)"]
    record = check_mentions("Swiftly stack the red block on the blue block.", schema)
    assert {"mention": "swiftly", "kind": "ignored",
            "consumed_by": "nothing: no meaning for the goal (reads like 'quickly')"} in record


@pytest.mark.parametrize("text, word, expected", [
    # issue 30, item 3: a word outside the lexicon that no class claims is ignored and listed (these had been refused)
    ("Put the red cube on the green patch, cc @kowalski", "kowalski", ["on_patch(red,patch:green)"]),
    ("Per Jenkins, put the red cube on the blue patch.", "jenkins", ["on_patch(red,patch:blue)"]),
])
def test_an_unknown_word_no_class_claims_is_ignored_and_listed(text, word, expected):
    """Only names, ids and jargon the dictionary does not know: ignoring every unclaimed word had
    moved the unseen split from 160 to 175 right but from 3 to 6 silently wrong (and 2 -> 4
    must-refuse compiled); ignoring nouns too still compiled 2 must-refuse texts."""
    from rpg.schema.builtin import check_mentions

    schema = parse(text)
    assert meaning(schema) == expected
    assert {"mention": word, "kind": "ignored",
            "consumed_by": "nothing: no meaning for the goal (reads like 'a word outside the lexicon')"} in check_mentions(text, schema)


@pytest.mark.parametrize("text, word", [
    # each of these compiled silently wrong when every unclaimed unknown word was ignored (measured on the
    # development sets): a word that may change what the task asks stays refused
    ("Create a three-level stack with blue block glued to green block, which is glued to red block.", "glued"),  # ("supported
    # by" is read since the thirty-first session: on top of)
    ("In the final scene there is a circle of red cubes; I count five of them.", "count"),
    ("Put teddy on top of the block tower, sweetie!", "teddy"),
    ("Line up the cubes from shortest to tallest.", "shortest"),
    ("Shape-8: eight cubes forming a hollow square outline.", "hollow"),
    ("All cubes shall be placed on the yellow patch, and all cubes shall likewise be placed on the blue patch.", "likewise"),
    ("Once the green block is next to the yellow block, put the pink block on top of the green one.", "once"),
    ("Put the digit cubes 1 to 5 in a row, left to right, so that they count down.", "count"),
    # words of the dictionary stay refused, whatever their part of speech
    ("Put the red block on the blue block, textbook!", "textbook"),
    ("We gave it this: put the red cube on the blue cube.", "gave"),
])
def test_an_unknown_word_that_may_carry_meaning_is_not_ignored(text, word):
    with pytest.raises(BadInput, match=f"'{word}'"):
        parse(text)


@pytest.mark.parametrize("text, word", [
    # words no dictionary knows, each caught by its own guard (the dictionary rule refuses real words first)
    ("yeet the red cube onto the blue cube", "yeet"),  # used as a verb on a cube
    ("Put the red cube zorp on the blue cube.", "zorp"),  # before a relation to a cube
    ("Put the red cube in the zorp.", "zorp"),  # a place
    ("Put the flurbo cube on the red patch.", "flurbo"),  # describes a cube
    ("Put blorp on the red cube.", "blorp"),  # what is placed
    ("Put the red cube on the blue cube. Zorp.", "zorp"),  # a sentence with nothing of the task
])
def test_a_made_up_word_that_may_carry_meaning_is_not_ignored(text, word):
    with pytest.raises(ParseError, match=f"'{word}'"):
        parse(text)


def test_a_text_mostly_of_unknown_words_is_refused_naming_them():
    """200 made-up tokens after a task had compiled with all of them ignored (found by the session's attack)."""
    with pytest.raises(ParseError, match="could not parse 'qwx'"):
        parse("Put the red cube on the blue cube " + " ".join(f"qwx{i}" for i in range(200)))


def test_a_question_about_a_cube_is_refused_as_a_question():
    from rpg.schema.builtin import Inexpressible

    with pytest.raises(Inexpressible) as exc:
        parse("Can the pink block fit on the cyan patch?")
    assert exc.value.kind == "question"
    assert meaning(parse("Could the robot place all four red cubes in a row?")) == ["line(red,red,red,red)"]


@pytest.mark.parametrize("text,expected", [
    # stranger20's silent errors (read after its first run was recorded)
    ("Make a row of alternating colours: red, white, red, white from left to right.",
     ["line[left_to_right](red,white,red,white)"]),  # six cubes had been made of the four listed
    ("Put a red cube at each end of a row of three, with a blue cube in between.",
     ["line[left_to_right](red,blue,red)"]),  # the ends had been dropped and a green cube made up
    ("Goal: letters B, E, D stacked to read BED from top to bottom.",
     ["reads(B,E,D;direction=top_to_bottom,face=front,text=BED)", "stack(D,E,B)"]),  # a line had been built
    ("From a start where blue sits on yellow, move the blue cube onto the red patch.",
     ["on_patch(blue,patch:red)", "start:stack(yellow,blue)"]),  # the start had been read as part of the goal
    ("Stack six cubes into one tower: two red at the bottom, two green in the middle, two blue at the top.",
     ["stack(red,red,green,green,blue,blue)"]),  # refused: "a colour listed twice is given an end"
    ("make tower of 3 cubes, white is bottom.", ["stack(white,red,blue)"]),  # no task found
    # stranger22 (read after its first run): both ends one colour (it had read white, white, brown: silently wrong)
    ("Tower of three: the top and bottom are both white, the middle one brown.", ["stack(white,brown,white)"]),
    ("Given a stack of orange on top of cyan, move the orange cube onto the pink patch.",
     ["on_patch(orange,patch:pink)", "start:stack(cyan,orange)"]),
    ("Build a 4-high tower, listed top to bottom: white, cyan, blue, purple.", ["stack(purple,blue,cyan,white)"]),
    ("Row of five cubes, colours unimportant, at the front of the table.", ["line(blue,green,orange,red,yellow)@front"]),
    ("Stack the cyan cube on the purple cube, and put the resulting tower in the front left corner.",
     ["stack(purple,cyan)@front_left"]),
    ("Three cubes of arbitrary colour must be stacked into a single tower.",
     ["stack(red,blue,green)"]),
])
def test_sequences_ends_and_starts_said_other_ways(text, expected):
    assert meaning(parse(text)) == expected


def test_a_start_the_reader_cannot_split_from_its_goal_is_refused():
    with pytest.raises(BadInput, match="from a start where"):
        parse("From a start where blue sits on yellow move the blue cube onto the red patch.")


def test_labels_spelled_one_by_one_are_not_ignored():
    with pytest.raises(BadInput, match="'b-a-d'"):  # a held-out set's silent error class: the tower's letters dropped
        parse("Build the tower B-A-D from bottom to top.")


def test_a_tower_end_said_as_a_field_must_agree_with_the_tower():
    with pytest.raises(ParseError, match="contradicts itself"):
        parse("Stack: yellow on pink; top cube: pink.")


@pytest.mark.parametrize("text, word", [
    ("Put the swift block on the red block.", "swift"),  # it describes a cube: which one?
    ("Stack the blocks diagonally.", "diagonally"),
    ("Put the red block sideways next to the blue block.", "sideways"),
])
def test_unknown_words_that_may_carry_meaning_stay_refused(text, word):
    with pytest.raises(ParseError, match=f"'{word}'"):
        parse(text)


@pytest.mark.parametrize("text, want", [
    ("Put the red block on the blue block's left.", ["left_of(red,blue)"]),  # compiled stack(blue,red)
    ("Place the red block at the blue block's front.", ["in_front_of(red,blue)"]),
    ("Put the red block far from the blue block.", ["far_from(blue,red)"]),
    ("Move the red block far away from the blue block.", ["far_from(blue,red)"]),
    ("Place the red and green blocks on either side of the blue block.", ["between(blue;green,red)"]),
])
def test_relations_said_by_a_cube_s_side_far_from_and_either_side(text, want):
    assert meaning(parse(text)) == want


def test_cubes_next_to_each_other_and_far_apart_is_a_contradiction():
    with pytest.raises(ParseError, match="contradict"):
        parse("Put the red block next to the blue block and far from it.")


def test_roles_said_with_is_bind_to_their_cubes():
    """"so that red is at the bottom, green in the middle and blue on top" compiled green at
    the bottom; "so that green is on top" fixed the other two cubes' order too."""
    assert meaning(parse("Stack the blocks so that red is at the bottom, green in the middle and blue on top.")) == [
        "stack(red,green,blue)"]
    goal = parse("Stack the red, green and blue blocks so that green is on top.").goal
    assert goal.name == "anchored_stack" and goal.top and not goal.bottom and goal.objects[-1] == "green"


def test_cubes_listed_with_articles_keep_their_stated_order():
    """"a yellow, a green and a blue block from left to right" lost its order."""
    assert meaning(parse("Line up a yellow, a green and a blue block from left to right.")) == [
        "line[left_to_right](yellow,green,blue)"]


def test_next_to_it_after_a_cube_put_on_a_patch_is_refused_not_read_as_on_the_patch():
    """"... on the red patch and the blue block next to it" put the blue block on the patch."""
    with pytest.raises(ParseError, match="next to it' may mean"):
        parse("Place the red block on the red patch and the blue block next to it.")


@pytest.mark.parametrize("text", ["Rotate the red block.", "Flip the green block over.", "Move the red block.", "Push the red block."])
def test_an_action_verb_with_nowhere_for_the_cube_to_end_says_no_end_state(text):
    """These were refused as "could not find a task", which names no reason."""
    with pytest.raises(ParseError, match="says no end state: '[a-z]+' is an action|a motion or a pose off the table, an action"):
        parse(text)


def test_the_no_end_state_refusal_quotes_the_user_s_verb():
    with pytest.raises(ParseError, match="'push' is an action"):
        parse("Push the red block.")


@pytest.mark.parametrize("text", [
    "Stack the red, green and blue blocks in any order.",
    "Put the red, green and blue blocks on top of each other, the order doesn't matter.",
    "Stack the yellow, red and blue cubes (any order is fine).",
])
def test_any_order_leaves_a_listed_stack_unordered(text):
    """"in any order" kept the listed order ("order" is an order word); "doesn't matter" was
    refused as a negation."""
    assert parse(text).goal.name == "unordered_stack"


@pytest.mark.parametrize("text, want", [
    ("Ok so basically I need the red cube sitting on top of the blue cube.", ["stack(blue,red)"]),
    ("Task: green cube on the yellow patch.", ["on_patch(green,patch:yellow)"]),
    ("For this task the robot should put the red block left of the blue block.", ["left_of(red,blue)"]),
    ("The robot must stack the red block on the green block.", ["stack(green,red)"]),
    ("Just put the red block behind the blue block, nothing fancy.", ["behind(red,blue)"]),
    ("Put the red cube so it is resting on the blue cube.", ["stack(blue,red)"]),
    ("Pile the yellow cube onto the green cube.", ["stack(green,yellow)"]),
    ("Place the red cube into the center of the green patch.", ["on_patch(red,patch:green)"]),
])
def test_framing_fillers_and_postures_say_nothing_of_the_goal(text, want):
    assert meaning(parse(text)) == want


def test_pile_onto_each_other_is_one_stack_not_piles_by_colour():
    """It compiled three separate piles, one per colour."""
    assert parse("Pile the red, green and blue blocks on top of each other.").goal.name == "unordered_stack"


def test_a_count_said_as_a_total_is_the_line_s_count():
    assert meaning(parse("Make a row of alternating blue and yellow blocks, four in total.")) == [
        "line[sequence](blue,yellow,blue,yellow)"]


def test_a_line_starting_with_its_first_colour_at_a_side_runs_from_that_side():
    """"starting with red on the left" was dropped (the line read from either end)."""
    assert meaning(parse("Make a row of alternating red and green blocks, four in total, starting with red on the left.")) == [
        "line[left_to_right](red,green,red,green)"]
    assert meaning(parse("Make a line of red, green and blue blocks starting with the red block on the right.")) == [
        "line[right_to_left](red,green,blue)"]


@pytest.mark.parametrize("text", ["Make a line of red, green and blue blocks with the blue block on the right.",
                                  "Make a line of red, green and blue blocks starting with the blue block on the right.",
                                  "Make a line of red, green and blue blocks from left to right with the red block on the right."])
def test_a_line_end_given_a_cube_the_goal_does_not_put_there_is_refused(text):
    """"with the blue block on the right" was dropped: any order of the three compiled."""
    with pytest.raises(ParseError, match="end"):
        parse(text)


def test_a_stack_put_on_a_patch_through_its_base_is_said_once():
    """"red on the blue block and the blue block on the green patch" was refused as stating
    'blue on green_patch' twice."""
    assert meaning(parse("Put the yellow block on the red block and the red block on the blue patch.")) == [
        "on_patch(red,patch:blue)", "stack(red,yellow)"]


@pytest.mark.parametrize("text, want", [
    ("Put the green block behind the red block, close to it.", ["behind(green,red)", "next_to(green,red)"]),
    ("Place the red block left of the blue block, next to it.", ["left_of(red,blue)", "next_to(blue,red)"]),
])
def test_a_relation_after_a_comma_keeps_the_subject_of_the_one_before(text, want):
    """"close to it" related the last-named cube to itself and was refused."""
    assert sorted(meaning(parse(text))) == sorted(want)


@pytest.mark.parametrize("text, want", [
    ("Put 3 red and 1 blue on the green patch.", ["on_patch(blue,red,red,red,patch:green)"]),
    ("Put 2 yellow + 2 green in a row.", ["line(green,green,yellow,yellow)"]),
])
def test_each_count_of_a_counted_colour_list_reaches_its_own_colour(text, want):
    """"2 blue and 2 green cubes" read one blue cube (the noun only after the last colour)."""
    assert meaning(parse(text)) == want


def test_a_height_said_for_each_of_two_coloured_towers_reaches_both():
    assert meaning(parse("Build a green tower and a yellow tower, each two blocks tall.")) == [
        "stack(green,green)", "stack(yellow,yellow)"]


def test_a_side_of_the_table_said_once_for_two_sides():
    assert meaning(parse("Put the green block on the front side and the red block on the back side of the table.")) == [
        "in_region(green,front)", "in_region(red,back)"]


@pytest.mark.parametrize("text, want", [
    ("Make a stack of 3 with green as the base.", "bottom"),
    ("Stack the three cubes so the blue one is at the bottom and the red one is at the top, the green one goes in between.", None),
])
def test_roles_said_as_the_base_or_in_between(text, want):
    goal = parse(text).goal
    if want:  # "with green as the base": one green cube at the bottom, not a tower of green cubes
        assert goal.name == "anchored_stack" and goal.bottom and not goal.top
        colours = [n.split("_")[0] for n in goal.objects]
        assert colours[0] == "green" and colours.count("green") == 1 and len(colours) == 3
    else:
        assert meaning(parse(text)) == ["stack(blue,green,red)"]


@pytest.mark.parametrize("text, color", [("Put a green block in each corner of the table.", "green"),
                                         ("Place four cubes, one in each corner.", None)])
def test_a_cube_in_each_corner(text, color):
    """It found no task; cubes of the colour said (or of one colour: any cube in any corner)."""
    schema = parse(text)
    assert sorted(p.region for p in schema.goal.children()) == ["back_left", "back_right", "front_left", "front_right"]
    colours = {a.color for a in schema.assets}
    assert len(colours) == 1 and (color is None or colours == {color})


@pytest.mark.parametrize("text, want", [
    ("Put 3 green blocks in a row along the front edge.", "line(green,green,green)@front"),
    ("Put three blocks in a line on the right.", "line(?,?,?)@right"),
    ("Build a pyramid of 3 blocks in the back right corner.", "pyramid(?,?,?)@back_right"),
    ("In the front left corner, build a 2x2 grid of blocks.", "grid(2x2:?,?,?,?)@front_left"),
])
def test_a_wide_structure_in_a_place_has_every_cube_there(text, want):
    """Lines, pyramids and grids in a region were refused; every cube must stand in it."""
    schema = parse(text)
    assert matches(want, meaning(schema)), meaning(schema)
    regions = [p for p in schema.goal.children() if p.name == "in_region"]
    assert len(regions) == len([a for a in schema.assets if a.kind != "goal_patch"])
    for p in regions:  # the goal layout (the witness the gates check) stands there too
        (x0, x1), (y0, y1) = region_boxes(p.region)[0]
        x, y, _ = schema.goal_layout[p.a].position
        assert x0 < x < x1 and y0 < y < y1


def test_a_structure_too_wide_for_its_place_is_refused():
    with pytest.raises(ParseError, match="does not fit|has no part"):
        parse("Put 5 blocks in a vertical line in the back right corner.")


@pytest.mark.parametrize("text, want", [
    ("Pick up the green block, then place it on the yellow block.", ["stack(yellow,green)"]),
    ("Grab the blue block then drop it on the red patch.", ["on_patch(blue,patch:red)"]),
    ("Slide the green block until it touches the red block.", ["next_to(green,red)"]),
    ("Push the yellow block against the blue block.", ["next_to(blue,yellow)"]),
    ("Push the red block until it reaches the blue patch.", ["on_patch(red,patch:blue)"]),
    ("Cover the yellow patch with the green block.", ["on_patch(green,patch:yellow)"]),
    ("Cover the red block with the blue block.", ["stack(red,blue)"]),
    ("The robot stacks the green block on the red block.", ["stack(red,green)"]),
    ("Push the blue block to the left half of the table.", ["in_region(blue,left)"]),
])
def test_verbs_of_contact_and_described_commands_say_their_end_state(text, want):
    """"until it touches" was refused as time, "against" and "cover" as unknown, "the robot
    stacks" read two towers, ", then place it" had no end state, "the left half" a quantity."""
    assert meaning(parse(text)) == want


@pytest.mark.parametrize("text, words", [
    ("Put the green block on this block.", "this block"),  # compiled a blue cube nobody named
    ("Put that cube on the yellow block.", "that cube"),
    ("Line up these blocks.", "these blocks"),
    ("Put those two cubes on the red patch.", "those two cubes"),
    ("Stack the cubes in this order.", "this order"),  # compiled a stack in any order
    ("Put the green block back on the block it was on.", None),
])
def test_cubes_or_an_order_pointed_at_in_the_speaker_s_scene_are_refused_as_references(text, words):
    with pytest.raises(Inexpressible) as info:
        parse(text)
    assert info.value.kind == "reference" and (words is None or f"'{words}'" in str(info.value))


@pytest.mark.parametrize("text, want", [
    ("Pick up the red block and put that block on the green block.", ["stack(green,red)"]),
    ("Stack the yellow, red and blue blocks in that order.", ["stack(yellow,red,blue)"]),
    ("Put this yellow block on the green block.", ["stack(green,yellow)"]),
])
def test_that_and_this_naming_or_listing_what_they_refer_to_still_compile(text, want):
    assert meaning(parse(text)) == want


@pytest.mark.parametrize("text", ["Is the green block to the left of the red block",  # no question mark
                                  "Can the yellow block be stacked on the green block?"])
def test_questions_without_a_mark_or_about_what_can_be_done_are_refused(text):
    with pytest.raises(Inexpressible) as info:
        parse(text)
    assert info.value.kind == "question"


def test_a_request_put_as_a_question_still_compiles():
    assert meaning(parse("Could you put the green block on the red block?")) == ["stack(red,green)"]


def test_a_triangle_with_nothing_stacked_names_no_one_shape():
    """It compiled an upright pyramid; a triangle may as well lie flat on the table."""
    with pytest.raises(ParseError, match="names no one shape"):
        parse("Arrange three blocks in a triangle.")
    assert parse("Stack three blocks in a triangle.").goal.name == "pyramid"


@pytest.mark.parametrize("text,expected", [
    # a list of labels whose last item follows a bare "and" keeps it (it dropped the 4, and D)
    ("Put the digit cubes 1, 2, 3 and 4 in a row from left to right.", ["line[left_to_right](1,2,3,4)"]),
    ("stack the letter cubes A, B, C and D", ["stack(A,B,C,D)"]),
    # a circle of listed labels has those cubes (it had six, A to F)
    ("put the letter cubes A, B, C and D in a circle", ["circle(A,B,C,D)"]),
])
def test_every_listed_label_is_a_cube_and_no_other(text, expected):
    assert meaning(parse(text)) == expected


def test_a_label_nobody_named_is_refused():
    with pytest.raises(ParseError, match="'X' has no place"):
        parse("put the letter cubes X, Y and Z in a circle")


@pytest.mark.parametrize("text,expected", [
    # a plural noun after a list of colours is the list's: one cube of each (it read two of the last colour)
    ("put the red and blue blocks on the yellow patch", ["on_patch(blue,red,patch:yellow)"]),
    ("put the red and the white blocks both on the yellow pad", ["on_patch(red,white,patch:yellow)"]),
    ("put the red, green and blue blocks on the yellow patch", ["on_patch(blue,green,red,patch:yellow)"]),
])
def test_a_plural_after_a_colour_list_is_one_cube_of_each(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    # two relations sharing one object: each is stated of it (the first was dropped)
    "Place the green block both to the left and to the right of the yellow block.",
    "put the red block to the left of and to the right of the blue block",
])
def test_relations_sharing_an_object_are_each_stated(text):
    with pytest.raises(ParseError, match="contradict"):
        parse(text)


def test_relations_sharing_an_object_compose():
    assert meaning(parse("put the red block next to and in front of the blue block")) == \
        ["in_front_of(red,blue)", "next_to(blue,red)"]


@pytest.mark.parametrize("text,match", [
    # "a tower of three" holds three: a tower of four or five read from a list of four colours is refused
    ("Build a tower of three blocks using the red, blue, green and white cubes", "asks for a tower of 3"),
    ("Build a tower of three blocks using the red, blue, green and white cubes, all four of them.", "asks for a tower of 3"),
    # each "a pink cube" is one more pink cube (the second merged into the first)
])
def test_a_counted_structure_holds_exactly_its_count(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


def test_it_after_a_cube_put_on_the_table_is_that_cube():
    assert meaning(parse("Place a pink cube on the table, put a cyan cube on it")) == ["stack(pink,cyan)"]


@pytest.mark.parametrize("text", [
    "stack the red, green, blue and yellow blocks into one tower -- the order is up to you",
    "stack the red and blue blocks in whatever order you like",
    # "from" without a "to" says what the tower is made of, not an order
    "Build a tower from two purple cubes and one black cube, in any order.",
])
def test_order_left_free_in_more_words(text):
    assert "in any order" in parse(text).goal_summary


@pytest.mark.parametrize("text,expected", [
    # a layer named by a comparative, or with its count, keeps its colour (the layers were lost)
    ("Construct a two-layer wall: the lower layer is two yellow cubes, the upper layer is two orange cubes.",
     ["wall(yellow,yellow|orange,orange)"]),
    ("build a wall: bottom layer two yellow cubes, top layer two orange cubes", ["wall(yellow,yellow|orange,orange)"]),
    # a layer's colours listed without commas (the layers had been swapped)
    ("Make me a wall: bottom row red red red, top row blue blue blue", ["wall(red,red,red|blue,blue,blue)"]),
    # "smallest to largest" of digits is their value, not a size
    ("line up the digits from smallest to largest",
     ["line[left_to_right](1,2,3,4)",
      "sorted_by(1,2,3,4;descending=False,direction=left_to_right,face=up,key=number,strict=True)"]),
])
def test_layers_and_values_said_in_more_words(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", ["Stack the blocks from largest at the bottom to smallest at the top.",
                                  "Place the larger of the two green cubes on the pink patch.", "sort the blocks by size"])
def test_a_size_compared_on_its_own_is_refused(text):
    with pytest.raises(Inexpressible, match="asks for a size") as exc:
        parse(text)
    assert str(exc.value).count("asks for a size") == 1


@pytest.mark.parametrize("text", [
    "The green cube is sitting on the yellow cube. Move the green cube down onto the table.",
    "The green cube is on the yellow cube. Move it onto the table.",
    "the green cube starts on the yellow cube; move it to the table",
])
def test_a_start_stated_then_a_cube_moved_to_the_table(text):
    assert meaning(parse(text)) == ["on_table(green)", "start:stack(yellow,green)"]


def test_a_cube_sent_to_the_table_is_not_left_stacked():
    with pytest.raises(ParseError, match="puts the red cube on the table"):
        parse("place the red block on the blue block, then move the red block to the table")


@pytest.mark.parametrize("text,expected", [
    ("The brown cube has to be placed on the cyan tile.", ["on_patch(brown,patch:cyan)"]),
    ("Push the green cube onto the red goal square.", ["on_patch(green,patch:red)"]),
    ("Cover the orange pad with the gray block.", ["on_patch(gray,patch:orange)"]),
    ("Set the black brick upon the pink brick.", ["stack(pink,black)"]),
    ("stack purpel on orange", ["stack(orange,purple)"]),  # two letters swapped
    ("put cyan cube at back right corner of table", ["in_region(cyan,back_right)"]),  # articles left out
    ("Goal state: on(red, green), on(green, blue).", ["stack(blue,green,red)"]),  # a planning predicate
    ("Goal: (on orange yellow) and (on yellow purple)", ["stack(purple,yellow,orange)"]),
    ("Put the pink block a long way from the orange block.", ["far_from(orange,pink)"]),
    ("the black cube and the white cube should be far apart", ["far_from(black,white)"]),
    ("Place the blue box-shaped block onto the green one.", ["stack(green,blue)"]),
    ("Arrange the letter cubes to spell out the name EVA.",
     ["line[left_to_right](E,V,A)", "reads(E,V,A;direction=left_to_right,face=up,text=EVA)"]),
    # an all-capital word is the word to spell, never an object ("book")
    ("spell BOOK with letter cubes", ["line[left_to_right](B,O,O,K)", "reads(B,O,O,K;direction=left_to_right,face=up,text=BOOK)"]),
    ("Build a 2-by-2 square out of two red and two blue cubes, flat on the table.", ["grid(2x2:blue,blue,red,red)"]),
    ("put the red cube on the green patch, and that's everything.", ["on_patch(red,patch:green)"]),
    ("Okay so here's what I want. Take the yellow cube and put it down in the back left corner.",
     ["in_region(yellow,back_left)"]),
])
def test_more_ways_people_say_it(text, expected):
    assert meaning(parse(text)) == expected


def test_a_cube_no_part_of_the_goal_names_is_refused():
    """A reading that makes a cube up and leaves it out of G is refused (a stray cube made while
    resolving 'it' compiled 'extra(red)' silently)."""
    from rpg.schema.accounting import unaccounted
    from rpg.schema.reading import features

    text = "put the red block on the blue block"
    schema = parse(text)
    stray = schema.assets[0].model_copy(update={"name": "white", "color": "white"})
    schema = schema.model_copy(update={"assets": [*schema.assets, stray]})
    assert "a cube (white) that no part of its goal names" in str(unaccounted(features(text), schema))


@pytest.mark.parametrize("text,expected", [
    # "over" in a chain is "on top of" (it was read as a bottom-to-top list: the order reversed)
    ("Create a stack of blocks: red over blue over purple over pink.", ["stack(pink,purple,blue,red)"]),
    ("put the red block over the blue block", ["stack(blue,red)"]),
    ("move the red block over to the left", ["in_region(red,left)"]),  # "over to": no relation
    # the centre of the table said as the table's, or as a "centered" structure (it was dropped)
    ("Take red block and green block, move them to the table's center, then stack green block on red block.",
     ["stack(red,green)@center"]),
    ("Build a centered stack with red block below green block and green block below blue block.",
     ["stack(red,green,blue)@center"]),
    ("make a centered row of three red cubes", ["line(red,red,red)@center"]),
    # "as its base" marks the base (the cube was added a second time)
    ("Move red block, green block, and blue block into a tower with red block as its base.", ["stack(red,green,blue)"]),
    ("Build a tower from bottom to top: red block, red block, blue block", ["stack(red,red,blue)"]),
    # the side a listed sequence starts from is its direction (it was an unordered line)
    ("Line up the objects in the order red block, green block, and blue block, starting from the left.",
     ["line[left_to_right](red,green,blue)"]),
    # "to the center" is the table's centre; "centrally", "the table's midpoint" say it too
    ("Shift red block and green block to the center and stack green block on red block.", ["stack(red,green)@center"]),
    ("Move red block to the middle and put green block on top of it.", ["stack(red,green)@center"]),
    ("Place red block and green block centrally, then stack green block on red block.", ["stack(red,green)@center"]),
    ("Relocate red block and green block to the table's midpoint, and stack green block on top of red block.",
     ["stack(red,green)@center"]),
    # the place said before the structure's "with": the whole structure there, the role kept
    ("Stack the red, green and blue blocks in the middle of the table with the blue block on top.",
     ["stack(red,green,blue)@center"]),
    # towers counted "of blocks", then listed after a colon
    ("Create two stacks of blocks: yellow over green over pink, and red over purple.",
     ["stack(pink,green,yellow)", "stack(purple,red)"]),
])
def test_more_ways_people_say_it_robotwin_and_vilain(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,bounds", [
    # a definite or bare "red block" said twice is one cube
    ("move red block, green block, and blue block into a tower with red block as its base",
     {"red": 1, "green": 1, "blue": 1}),
    ("move the red block next to the blue block, then put the red block on the green patch", {"red": 1, "blue": 1}),
    # an indefinite after a definite is one more; "the other" is one more
    ("place a purple block on the red block. then a red block then a green block.",
     {"purple": 1, "red": 2, "green": 1}),
    ("put the red block on the other red block", {"red": 2}),
    ("stack two red blocks", {}),  # a count: not bounded here (the count bounds it)
    # each item of a list is a cube of its own (the bound made the parser drop one)
    ("build a tower from bottom to top: red block, red block, blue block", {"red": 2, "blue": 1}),
])
def test_a_colour_named_as_single_cubes_bounds_how_many_there_are(text, bounds):
    from rpg.schema.accounting import _single_color_bounds

    assert _single_color_bounds(text) == bounds


def test_a_cube_said_twice_is_not_two_cubes():
    """A reading that adds a cube a second time because a role named it again is refused."""
    from rpg.domain.predicates import Stack
    from rpg.schema.accounting import unaccounted
    from rpg.schema.reading import features

    text = "Stack the red block, the green block and the blue block with the red block at the bottom."
    schema = parse(text)
    red = next(a for a in schema.assets if a.color == "red")
    extra = red.model_copy(update={"name": "red_2"})
    stack = next(p for p in schema.goal_predicate().walk() if isinstance(p, Stack))
    schema = schema.model_copy(update={"assets": [*schema.assets, extra], "goal": Stack((*stack.objects, "red_2"))})
    assert "names one red cube but the task read has 2" in str(unaccounted(features(text), schema))


@pytest.mark.parametrize("text,match", [
    # a side said alone is one end of a relation only when the other side is said too
    ("Grab red block, position it on the left. Next, grab green block to place beside red block, then grab blue "
     "block and set it to the right of green block.", "the place 'left' has no part"),
    # two colours run together inside a chain: a dropped "over" or "and"
    ("Create a stack of blocks: orange over yellow over blue purple over red.", "two colours with nothing between"),
])
def test_what_a_chain_or_a_side_leaves_unclear_is_refused(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


@pytest.mark.parametrize("text,words", [
    # a cube picked by where it stands now: a relative clause, "from" a place, what the speaker sees or holds
    ("move the red block that is on the blue block to the green patch", "the red block that is on"),
    ("take the block from the green patch and put it on the red patch", "take the block from the"),
    ("put the block I'm looking at on the red patch", "looking at"),
    ("stack the block I see on the red patch", "i see"),
    ("put the brick I'm holding on the red patch", "holding"),
    ("put the cube in my hand on the red patch", "in my hand"),
    # a place picked by contrast with one nobody named
    ("move the block to the other patch", "the other patch"),
    ("put the red block on the other side of the table", "the other side"),
    # moved relative to where it stands now
    ("move the red block closer to the blue block", "closer to"),
    ("move the red block a bit to the left", "a bit to the left"),
    ("push the two blocks closer together", "closer together"),
    # a cube picked by what stands on it, or by a relation said as a description
    ("put the red block on the block that the blue block is on", "the block that the blue block is on"),
    ("the red block, which is next to the blue one, goes on the green patch", "which is next to"),
    # a structure moved that nobody described (a default tower had been invented for it)
    ("put the tower centrally", "put the tower"),
    ("move the row to the left side of the table", "move the row"),
])
def test_what_only_the_current_scene_says_is_refused_as_a_reference(text, words):
    with pytest.raises(Inexpressible) as err:
        parse(text)
    assert err.value.kind == "reference" and words in str(err.value), str(err.value)


@pytest.mark.parametrize("text,expected", [
    ("put the blue block on the green block, which is on the red block", ["stack(red,green,blue)"]),  # a goal chain
    ("put the red block on the green patch and the blue block on the other patch",
     ["on_patch(blue,patch:gray)", "on_patch(red,patch:green)"]),  # the contrast is said
    ("put block I on block J", ["stack(J,I)"]),  # the letter I, not the speaker
    ("put the red block far from the blue block", ["far_from(blue,red)"]),
    ("make a row of three red blocks and move the row to the back", ["line(red,red,red)@back"]),  # described first
])
def test_what_looks_like_a_reference_but_is_said_compiles(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a line's cubes given their places in it: the order, left to right
    ("Arrange red block, green block, and blue block in a row with red block on the left, green block in the middle, "
     "and blue block on the right.", ["line[left_to_right](red,green,blue)"]),
    ("Place the orange, purple, and pink cubes in a row so that orange is leftmost, purple is in the middle, and pink "
     "is rightmost.", ["line[left_to_right](orange,purple,pink)"]),
    ("Arrange red, green and blue in a row with blue on the left and red on the right.",
     ["line[left_to_right](blue,green,red)"]),
    # a cube's end of the line is no place of the line (it compiled the line at the table's left)
    ("Line up the yellow and blue blocks with blue on the left", ["line[left_to_right](blue,yellow)"]),
    # the cubes named, then their order after the direction words (the first list was taken)
    ("Arrange red block, green block, and blue block in a row, from left to right: blue, green, red.",
     ["line[left_to_right](blue,green,red)"]),
    ("Construct a four-block tower. Starting with brown at the base, add yellow, then orange, and finish with a white "
     "cube at the top.", ["stack(brown,yellow,orange,white)"]),
])
def test_a_line_s_order_said_by_its_cubes_places(text, expected):
    assert meaning(parse(text)) == expected


def test_two_lists_in_different_orders_are_refused():
    with pytest.raises(ParseError, match="two different orders"):
        parse("Arrange red, green and blue in a row: blue, green, red.")


@pytest.mark.parametrize("text,expected", [
    # the place after a second cube is that cube's (it went to the first relation's cube)
    ("Put the red cube on the green patch, the blue cube on the yellow patch, and the white cube in the center of the "
     "table.", ["in_region(white,center)", "on_patch(blue,patch:yellow)", "on_patch(red,patch:green)"]),
    ("stack the red block on the blue block in the back left corner", ["stack(blue,red)@back_left"]),
    # "the right half" after "the left half of the table" is the table's too
    ("Move the black cube to the left half of the table and the white cube to the right half.",
     ["in_region(black,left)", "in_region(white,right)"]),
    ("Keep the green cube far from the yellow cube.", ["far_from(green,yellow)"]),
    ("The black block is on the white block, and the white block is on the gray block. Make this true.",
     ["stack(gray,white,black)"]),
])
def test_places_and_closings_said_in_more_words(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # found by a helper attacking the session's changes
    ("put the red block over near the blue block", ["next_to(blue,red)"]),  # "over" as an adverb is no "on top of"
    ("put the red block at the midpoint between the blue and the green block", ["between(red;blue,green)"]),
    ("put the red block centrally between the blue and green blocks", ["between(red;blue,green)"]),
    ("put the red block in the middle of the table between the blue and green blocks",
     ["between(red;blue,green)", "in_region(red,center)"]),  # the table's middle said: kept
    ("make a row of blue, red and green, starting from the left with blue", ["line[left_to_right](blue,red,green)"]),
    ("put the red block on the green patch and the blue block on the same patch", ["on_patch(blue,red,patch:green)"]),
    ("line up red, green and blue from left to right: blue, green, red", ["line[left_to_right](blue,green,red)"]),
])
def test_attacked_phrasings_read_as_said(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,match", [
    ("build a tower of over three blocks", "quantity"),
    ("build a tower with at least 3 red blocks", "quantity"),
    ("build a centered stack of red, blue and green", "'centered'"),
    # "the red block ... a red block" is two red cubes (one cube was put on both patches)
    ("put the red block on the green patch and a red block on the yellow patch", "2 red cubes"),
    ("make a row of red, green and blue with red on the left, blue in the middle and blue on the right", "two cubes in one place"),
])
def test_attacked_phrasings_refused(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


def test_finish_with_outside_a_sequence_is_not_read_as_one():
    """"a tower of four blocks and finish with red" compiled a tower in any order (red's place dropped)."""
    with pytest.raises(ParseError):
        parse("build a tower of four blocks and finish with red")


@pytest.mark.parametrize("text,expected", [
    # a plural noun after two colours names two of them (yellow had been read as a cube)
    ("the white cube should be between the yellow and the pink patches", ["between(white;patch:pink,patch:yellow)"]),
    ("put the red cube between the yellow and the pink patch", ["between(red;patch:pink,patch:yellow)"]),  # singular
    # two cubes on two patches, pair by pair
    ("put the red and the blue cubes onto the yellow and green patches, respectively.",
     ["on_patch(blue,patch:green)", "on_patch(red,patch:yellow)"]),
])
def test_two_colours_before_one_plural_patch_noun_name_two_patches(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # the middle of the list had been kept in its order between the swapped ends (4, 2, 3, 1)
    ("Stack the digit cubes 1, 2, 3 and 4 into one tower, 4 at the bottom and 1 on top.", ["stack(4,3,2,1)"]),
    # a label named again for its end is not one more cube (it had stacked D twice)
    ("stack letters A, B, C and D, D at the bottom and A on top", ["stack(D,C,B,A)"]),
    # a colour listed twice gets its end from the end of the list it stands at
    ("stack red, blue, red, blue with blue on top", ["stack(red,blue,red,blue)"]),
    ("stack red, blue, red, blue with blue at the bottom", ["stack(blue,red,blue,red)"]),
    # a count after "of" alone, and a colour for every tower of a count (two towers had lost it)
    ("build a tower of three", ["stack(red,blue,green)"]),
    ("build two towers, 3 blocks high, all green", ["stack(green,green,green)", "stack(green,green,green)"]),
])
def test_a_tower_list_is_read_from_the_end_its_roles_name(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "a pyramid of four",  # no pyramid of cubes has four (six had been built)
    "build a tower of three: red base, then blue, then red, then blue on top",  # four listed
    "build a tower of four: red base, then blue, then red on top",  # three listed (a green had been invented)
    "put the red cube left of the blue cube, the green cube behind the white cube and the brown cube far from both of them",
])
def test_a_count_or_a_reference_the_list_does_not_match_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text,kind,words", [
    # each had compiled, dropping the words (stranger set 3)
    ("Stack red on blue, but only after the blue block has been moved to the center.", "condition", "only after"),
    ("Put the block that was just moved next to the blue block.", "reference", "that was just moved"),
])
def test_an_order_of_events_or_a_cube_picked_by_one_is_refused_for_it(text, kind, words):
    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert exc.value.kind == kind and words in str(exc.value)


def test_one_cube_on_two_goal_patches_is_refused_as_a_contradiction():
    with pytest.raises(Inexpressible) as exc:  # it had compiled a goal no episode can reach
        parse("Put the white cube on the black patch and on the red patch.")
    assert exc.value.kind == "contradiction" and "white on black patch and on red patch" in str(exc.value)


@pytest.mark.parametrize("text,expected", [
    # a coloured square a cube is put on is a patch (it had compiled a 2x2 grid)
    ("Please put the blue block onto the yellow square, and the red block onto the green square.",
     ["on_patch(blue,patch:yellow)", "on_patch(red,patch:green)"]),
    ("build a red square", ["grid(2x2:red,red,red,red)"]),  # a square built is a structure
])
def test_a_coloured_square_a_cube_goes_on_is_a_patch(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # one of the two had been dropped
    ("Put the orange cube next to the purple cube, and put the brown cube far from both of them.",
     ["far_from(brown,orange)", "far_from(brown,purple)", "next_to(orange,purple)"]),
    ("place the red and blue cubes next to each other and put the brown cube far from the two of them",
     ["far_from(blue,brown)", "far_from(brown,red)", "next_to(blue,red)"]),
    ("put the red cube left of the blue cube and the brown cube far from all of them",
     ["far_from(blue,brown)", "far_from(brown,red)", "left_of(red,blue)"]),
])
def test_a_relation_to_both_of_them_reaches_the_two_cubes_named_before(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # both sides said with "side": the table's sides (it had compiled a relation between the two cubes)
    ("Please put the blue cube on the left side and the green cube on the right side.",
     ["in_region(blue,left)", "in_region(green,right)"]),
    ("put the red block on the left and the blue block on the right", ["left_of(red,blue)"]),  # bare sides: a relation
])
def test_two_sides_said_as_sides_are_the_table_s(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # each was refused (stranger set 3): a non-native "at top of", a greeting, colour typos, a pyramid's "peak"
    ("Please you put the red cube at top of the green cube.", ["stack(green,red)"]),
    ("yo stack yellow on pink", ["stack(pink,yellow)"]),
    ("place blu cube on top of the gren cube", ["stack(green,blue)"]),
    ("Build a pyramid with three blue blocks on the base, two red blocks above them and a yellow block at the peak.",
     ["pyramid(blue,blue,blue|red,red|yellow)"]),
])
def test_harmless_words_of_other_writers_are_read(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # tasks said one after another with no cube in common: each read alone, laid out apart
    ("make a tower of two blue blocks and put the red block in the front left corner",
     ["in_region(red,front_left)", "stack(blue,blue)"]),
    ("build a row of three green cubes. Put the red cube on the yellow patch",
     ["line(green,green,green)", "on_patch(red,patch:yellow)"]),
    ("Make a pyramid of three orange cubes and put the cyan cube behind the gray cube.",
     ["behind(cyan,gray)", "pyramid(orange,orange,orange)"]),
    # a side said of a structure the part describes is the table's; "and a <structure>" begins a part
    ("Line of 3 green cubes at the back; tower of 2 pink cubes at the front.",
     ["line(green,green,green)@back", "stack(pink,pink)@front"]),
    ("Make a circle of four red cubes on the left and a cirlce of four blue cubes on the right.",
     ["circle(blue,blue,blue,blue)@right", "circle(red,red,red,red)@left"]),
    ("build a red tower on the left and a blue tower on the right", ["stack(blue,blue)@right", "stack(red,red)@left"]),
])
def test_independent_parts_are_read_apart_and_laid_out_clear_of_each_other(text, expected):
    from rpg.schema.readers.compose import PART_CLEARANCE

    schema = check_feasibility(parse(text))
    assert meaning(schema) == expected
    goal = schema.goal_predicate()
    parts = [set(p.object_names()) for p in goal.children()]
    xy = {n: np.array(p.position[:2]) for n, p in schema.goal_layout.items()}
    placed = {p.a for p in goal.walk() if p.name == "in_region"}  # parts in places of their own keep to them
    for i, a in enumerate(parts):  # no cube of one part within a cube edge plus the clearance of another's
        for b in parts[i + 1:]:
            if not a & b and not (a & placed and b & placed):
                assert min(np.abs(xy[m] - xy[n]).max() for m in a for n in b) >= 0.04 + PART_CLEARANCE - 1e-9


@pytest.mark.parametrize("text", [
    "make a tower of two blue blocks and put the red block on the left",  # the tower's left, or the table's?
    "build a tower of three blocks and put the red block next to it",  # one part refers to another
    # found by the attack: each had been read apart, dropping what ties the parts
    "put the red block in the front left corner and stack two blue blocks there",
    "build a line of three green cubes and put the red cube in the middle",
    "make a tower of three blue blocks and make a row of the other three",
    "build a tower of three green cubes. Put a second tower of two red cubes in the back right corner",
    "put the red cube on the yellow patch. Then build a tower of the blue and green cubes on it",
    # labels are not told apart by colour (a second "2" had been invented)
    "Place the numbers 1 to 3 in a row, then stack the number 4 on top of the number 2",
])
def test_parts_that_may_refer_to_one_another_are_not_read_apart(text):
    from rpg.schema.builder import Builder
    from rpg.schema.readers.compose import recognize_independent_parts
    from rpg.schema.reading import features

    f = features(text)
    assert not recognize_independent_parts(f, Builder(f.original))


@pytest.mark.parametrize("text,expected", [
    # stranger set 5: a structure's place said just after its noun, or the structure put there afterwards
    ("Build a 4-high tower in the centre: yellow at the bottom, then orange, then red, then purple at the top.",
     ["stack(yellow,orange,red,purple)@center"]),
    ("Stack the pink cube on the white cube, and put that tower on the left.", ["stack(white,pink)@left"]),
    ("Wall: bottom row three grey blocks, top row three brown blocks. Put it at the back of the table.",
     ["wall(gray,gray,gray|brown,brown,brown)@back"]),
    # a wall's width from the cubes counted for each layer (had been a 2x2 wall that dropped cubes)
    ("A wall two layers high. Bottom layer: four orange bricks. Top layer: four purple bricks.",
     ["wall(orange,orange,orange,orange|purple,purple,purple,purple)"]),
    # a layer given its colour without an article (had dropped the layers: silently wrong)
    ("a wall of 6 blocks, red bottom row, blue top row", ["wall(red,red,red|blue,blue,blue)"]),
    # a tower's ends given without a preposition (had put red at the bottom: silently wrong)
    ("build a tower: red top, blue bottom", ["stack(blue,red)"]),
    ("A tower of four: red base, then blue, then red, then blue on top.", ["stack(red,blue,red,blue)"]),
    # a place said bare in a list item or a heading (the spec had dropped both places: silently wrong)
    ("Spec: (1) tower of three yellow blocks, back-left corner; (2) line of three blue blocks, front of the table.",
     ["line(blue,blue,blue)@front", "stack(yellow,yellow,yellow)@back_left"]),
    ("Red cube: front of the table.", ["in_region(red,front)"]),
    ("Pyramid at the back: four purple cubes at the bottom, then three, then two, then one, all purple.",
     ["pyramid(purple,purple,purple,purple|purple,purple,purple|purple,purple|purple)@back"]),
    # a pyramid's size from the cubes counted at its base (had invented three cubes: silently wrong)
    ("pyramid, 2 white on the bottom and 1 black on top, right side of table", ["pyramid(white,white|black)@right"]),
    # "far away from both of them" after a verb; harmless negations and framing
    ("the cyan cube goes next to the pink one, and the grey cube goes far away from both of them",
     ["far_from(cyan,gray)", "far_from(gray,pink)", "next_to(cyan,pink)"]),
    ("Set the white cube down to the left of the green cube, if you don't mind.", ["left_of(white,green)"]),
    ("Two things: stack the A cube on the C cube, and put the B cube next to the C cube.", ["next_to(B,C)", "stack(C,A)"]),
    # a row of digits in an order says nothing of reading them (their faces up): no reads(...)
    ("Make a row of the digits 3, 1, 4 from left to right.", ["line[left_to_right](3,1,4)"]),
    # typos and orders of a stranger's places; the two patches named before; "one ... the other"; two same-colour patches
    ("put the gray cube infront of the green patch", ["in_front_of(gray,patch:green)"]),
    ("Put the red block in the right back corner.", ["in_region(red,back_right)"]),
    ("Front-left corner: the green cube.", ["in_region(green,front_left)"]),
    ("Put the white block on the black patch and the black block on the white patch, then put the red block between the "
     "two patches.", ["between(red;patch:black,patch:white)", "on_patch(black,patch:white)", "on_patch(white,patch:black)"]),
    ("Put one yellow block on the red patch and the other yellow block on the blue patch.",
     ["on_patch(yellow,patch:blue)", "on_patch(yellow,patch:red)"]),
    ("Put the blue cube between the two yellow patches.", ["between(blue;patch:yellow,patch:yellow)"]),
    # each cube of a row given its place after a colon (the places had been read as the table's)
    ("Put three cubes in a row: red at the left end, blue at the right end, yellow in the middle.",
     ["line[left_to_right](red,yellow,blue)"]),
    ("make a row: red on the left, blue on the right, green in the middle", ["line[left_to_right](red,green,blue)"]),
    # a cube "with one ... in the middle" of a tower whose ends are said (it had gone to the table's centre: silently wrong)
    ("Make a tower with blue at the bottom and yellow on top, with one red block in the middle.", ["stack(blue,red,yellow)"]),
    ("Make a tower whose base is blue and whose top is yellow, with one red block in between.", ["stack(blue,red,yellow)"]),
    # label cubes named by their label alone (had been read as two invented red and blue cubes)
    ("stack the A on the B", ["stack(B,A)"]),
    ("Stack the 1 on the 2, and the 3 on the 4 (number cubes).", ["stack(2,1)", "stack(4,3)"]),
    # the stack's cubes are those of its clause (the cyan cube moved to a corner had become its base)
    ("Move the cyan cube to the back left corner. Stack the two brown cubes in the front right corner.",
     ["in_region(cyan,back_left)", "stack(brown,brown)@front_right"]),
    # "that patch" is the one patch named before (a second, gray patch had been invented)
    ("Put the red and yellow cubes together on the white patch, and put the blue cube far from that patch.",
     ["far_from(blue,patch:white)", "on_patch(red,yellow,patch:white)"]),
])
def test_places_and_layers_said_by_a_fifth_writer(text, expected):
    assert meaning(parse(text)) == expected


def test_a_place_said_after_a_structure_s_noun_is_every_cube_s():
    schema = parse("Build a 4-high tower in the centre: yellow at the bottom, then orange, then red, then purple at the top.")
    regions = [p for p in schema.goal_predicate().walk() if p.name == "in_region"]
    assert len(regions) == 4 and {p.region for p in regions} == {"center"}


@pytest.mark.parametrize("text", ["Hiya! Could you make me a tower out of the red, blue and green blocks? Whatever order "
                                  "you like, I'm not fussy.",
                                  "stack 2 yellow + 2 black blocks into a single tower, order doesnt matter"])
def test_order_left_free_in_a_stranger_s_words_gives_an_unordered_stack(text):
    from rpg.domain.predicates import UnorderedStack

    goal = parse(text).goal_predicate()
    assert any(isinstance(p, UnorderedStack) for p in goal.walk()), goal


def test_a_negation_that_is_not_about_the_end_state_is_still_refused():
    with pytest.raises(ParseError, match="negation"):
        parse("don't put the red block on the blue block, if you don't mind")


@pytest.mark.parametrize("text,match", [
    ("put the red on the white patch and the blue on the green patch and the yellow next to the patch", "which patch"),
    # plural patches of one colour had collapsed into one patch holding both cubes (silently wrong)
    ("put the red cubes on the two green patches", "2 green patches"),
    ("put the two red cubes on the green patches", "2 green patches"),
    # a wall nobody built is no wall: six red cubes in the centre had been read with no wall
    ("Build a wall of six red bricks (three on the bottom, three on top) in the centre, and put the white brick in the "
     "front left corner.", "Rephrase"),
])
def test_a_patch_or_structure_that_cannot_be_told_is_refused(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


def test_word_salad_that_asks_for_more_open_colours_than_there_are_is_refused_not_a_crash():
    with pytest.raises(ParseError):
        parse("stack 'CAT' then pyramid 3x3")


def test_another_cube_of_a_colour_is_a_cube_of_its_own():
    schema = parse("put the red block on the blue block and another red block next to the blue block")
    assert sorted(a.name for a in schema.assets) == ["blue", "red_1", "red_2"]
    assert meaning(parse("put the green block on the blue patch, then put a second green block on the blue patch")) == [
        "on_patch(green,green,patch:blue)"]


def test_a_sentence_that_says_nothing_of_the_task_is_dropped_not_refused():
    from rpg.schema.reading import normalize_words

    said = "Stack the red block on the blue block. My supervisor wants this for the demo."
    assert meaning(parse(said)) == ["stack(blue,red)"]
    _, _, dropped = normalize_words(said)
    assert {"supervisor", "demo"} <= {w for w, _ in dropped}  # listed, not silently gone
    # a sentence that may change the task is not idle (found by the attack: each had been dropped): still refused
    for text in ("Stack red on blue. Vice versa.", "Put the red cube on the blue cube. Beneath, I mean.",
                 "Line up the red, green and blue cubes. Diagonal please.", "Stack the red block on the blue block. Offset.",
                 "Stack the red block on the blue block. Lying down.", "Put the red cube on the left. Mirrored."):
        with pytest.raises(ParseError):
            parse(text)
    # a sentence with a reference ("it") or a negation is not idle: still refused
    with pytest.raises(ParseError, match="gracefully"):
        parse("Stack the red block on the blue block. Do it gracefully.")
    with pytest.raises(ParseError, match="negation"):
        parse("Stack the red block on the blue block. Never mind.")


def test_two_towers_of_unnamed_cubes_said_in_one_sentence_are_two_unordered_towers():
    from rpg.domain.predicates import UnorderedStack

    schema = parse("build a tower of 5 and a tower of 2")
    stacks = [p for p in schema.goal_predicate().walk() if isinstance(p, UnorderedStack)]
    assert sorted(len(p.objects) for p in stacks) == [2, 5] and len(schema.assets) == 7


@pytest.mark.parametrize("text,expected", [
    # label cubes listed each with its article (a fourth letter had been invented, or the order dropped)
    ("line up the A, the B and the C from left to right", ["line[left_to_right](A,B,C)"]),
    ("line up the 1, the 2 and the 3 from left to right", ["line[left_to_right](1,2,3)"]),
    # a line of labels with no direction or order said: which cubes, not where (the listed order had been kept from
    # either end until the forty-sixth session: a goal stricter than its words, as no list of colours is)
    ("put the A and the B in a line", ["line(A,B)"]),
    ("Place the 7, 8 and 9 cubes side by side in a row along the back of the table.", ["line(7,8,9)@back"]),
    ("Put the digits 1, 2 and 3 in a row in order.", ["line[sequence](1,2,3)"]),
    # a word that may place a listed label in its row keeps the listed order (a hostile probe: the roles had been dropped)
    ("Put the letter cubes X, Y and Z in a row with Y at the centre", ["line[sequence](X,Y,Z)"]),
    ("Put the digit cubes 3, 1 and 2 in a row: 3, then 1, then 2", ["line[sequence](3,1,2)"]),
    ("Put the digit cubes 3, 1 and 2 in a row, in this exact sequence", ["line[sequence](3,1,2)"]),
])
def test_label_cubes_listed_one_by_one(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", ["Put the pink cube on the orange patch and far from the orange patch",
                                  "Put the pink cube on the orange patch, and keep it far away from the orange patch.",
                                  "put the red block on the blue block and far from the blue block"])
def test_touching_and_far_apart_is_a_contradiction(text):
    with pytest.raises(ParseError, match="contradict"):
        parse(text)


@pytest.mark.parametrize("text,match", [
    # found by the attack: each had compiled with a patch nobody named, or a relation to one of two patches
    ("put the red cube on the green patch and blue on the yellow patch, and the white cube behind the two patches",
     "two patches at once"),
    ("put the red cube on the green patch and the blue cube between the two patches", "Rephrase"),
    ("put the red and blue cubes on both patches", "2 goal patches"),
    # "together" is said: some predicate must put the cubes together (it had been dropped)
    ("place the red and blue blocks together. the yellow block should be far away from both of them", "together"),
])
def test_patches_and_together_nobody_placed_are_refused(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # found by the attack: layers said one after another, a layer's "all", a tower "at the back of" a cube
    ("pyramid with 3 blue at the base then 2 red then 1 yellow", ["pyramid(blue,blue,blue|red,red|yellow)"]),
    ("a wall of 6 blocks, 3 wide, top row all purple", ["wall(blue,green,red|purple,purple,purple)"]),
    ("build a tower of red and blue at the back of the green cube", ["behind(blue,green)", "behind(red,green)", "stack(red,blue)"]),
])
def test_layers_and_places_the_attack_found(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "a pyramid of 3 blocks: red and blue on the bottom, all purple",  # every cube purple, and some not
    "put the blue cube down, and a tower of 3 red cubes on the left",  # a green cube had been made up for the tower
])
def test_structures_with_colours_nobody_said_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text", ["Build a tower of red, blue and green. Reverse the order.",
                                  "Line up red, green and blue from left to right. Backwards.",
                                  "Stack red on blue. Then flip it."])
def test_a_last_sentence_that_turns_the_order_around_is_refused(text):
    """Found by the attack: each compiled in the order the speaker had just taken back."""
    with pytest.raises(ParseError, match="turns around"):
        parse(text)


def test_a_word_spelled_backwards_reads_reversed():
    assert meaning(parse("spell CAT backwards")) == ["line[left_to_right](T,A,C)",
                                                       "reads(T,A,C;direction=left_to_right,face=up,text=TAC)"]


@pytest.mark.parametrize("text,expected", [
    # found by the attack: a corner said without "corner", "in back", a place after the second of two structures
    # (each place had been dropped, or given to both structures)
    ("a tower of 3 blocks at the front right: red bottom, blue middle, green top", ["stack(red,blue,green)@front_right"]),
    ("stack red on blue, front left", ["stack(blue,red)@front_left"]),
    ("build a tower of 2 red blocks in back", ["stack(red,red)@back"]),
    ("a tower of 3 red blocks and a line of 3 blue blocks on the right", ["line(blue,blue,blue)@right", "stack(red,red,red)"]),
])
def test_places_the_attack_found_dropped(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # two cubes at opposite sides, and a structure's place said last after a comma (each had been refused)
    ("put the red cube at the front and the blue cube at the back", ["in_region(blue,back)", "in_region(red,front)"]),
    ("build a wall: 3 red on the bottom, 3 blue on top, at the back", ["wall(red,red,red|blue,blue,blue)@back"]),
    ("I'd like the yellow cube in the front-left corner and the cyan cube in the back-right corner",
     ["in_region(cyan,back_right)", "in_region(yellow,front_left)"]),
])
def test_sides_said_of_two_cubes_or_after_a_structure(text, expected):
    assert meaning(parse(text)) == expected


def test_another_patch_of_a_colour_is_a_patch_of_its_own_and_the_2_on_each_other_are_two_cubes():
    """Found by the attack: both cubes had shared one green patch; "the 2" had become two digit-2 cubes."""
    schema = parse("put a red cube on a green patch and the blue cube on another green patch")
    assert sorted(a.name for a in schema.assets if a.kind == "goal_patch") == ["green_patch_1", "green_patch_2"]
    assert not any(a.kind == "semantic_cube" for a in parse("stack the 2 on top of each other").assets)


@pytest.mark.parametrize("text,expected", [
    # stranger6 (eighth session): framing, politeness and free-choice words that had been refused as a condition,
    # a negation or an unknown word; the goal is read as if they were not there
    ("Goal state: the green cube rests directly on the red cube. All other cubes may be anywhere.", ["stack(red,green)"]),
    ("Hey robot! Hope you're doing well. Today I'd love it if you could take the yellow cube and put it right on top "
     "of the purple one. Thanks a bunch!", ["stack(purple,yellow)"]),
    ("Success condition: the purple block lies within the white goal patch.", ["on_patch(purple,patch:white)"]),
    ("put da green block on da red patch", ["on_patch(green,patch:red)"]),
    ("pls put the grey cube rite of the white one", ["right_of(gray,white)"]),
    ("Put the yellow block on top of the red block, which should sit on the blue patch.",
     ["on_patch(red,patch:blue)", "stack(red,yellow)"]),
    ("Task spec \u2014 blocks: red, blue, green. Goal: blue cube to the left of red cube; green cube to the right of red cube.",
     ["left_of(blue,red)", "right_of(green,red)"]),
    ("my supervisor wants the white cube on the left side of the table, doesn't matter exactly where",
     ["in_region(white,left)"]),
    ("At the end, the red cube should be on the blue cube. Nothing else matters.", ["stack(blue,red)"]),
])
def test_framing_politeness_and_free_choice_are_not_the_goal(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,kind", [
    ("If the green cube is on the left, put it on the yellow patch.", "condition"),  # a real condition stays one
    ("Put the red cube on the blue cube if the blue cube is on the left.", "condition"),
    ("Put the blue cube anywhere except the left side of the table.", "negation"),
    ("The orange cube must not be next to the purple cube.", "negation"),
])
def test_conditions_and_negations_that_are_not_politeness_stay_refused(text, kind):
    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert kind in {k for k, _, _ in exc.value.reasons}


@pytest.mark.parametrize("text,expected", [
    # stranger6 (eighth session): each compiled silently wrong before
    ("Final configuration: a 3-layer pyramid (3-2-1) of gray cubes positioned at the table centre.",
     ["pyramid(gray,gray,gray,gray,gray,gray)@center"]),  # "the table centre" had been dropped
    ("Build a tower of digit cubes 9, 8, 7 with 9 on top.", ["stack(7,8,9)"]),  # the list read from the top it names
    ("stack em all up: red green blue yellow, red first", ["stack(red,green,blue,yellow)"]),  # not a fifth, red cube
    # a wall's layers listed cube by cube (each layer had taken only its first colour)
    ("Build a wall with a bottom row of blue, green, blue and a top row of green, blue, green.",
     ["wall(blue,blue,green|blue,green,green)"]),
    ("build a wall: bottom row red, red, blue; top row blue, blue, red", ["wall(blue,red,red|blue,blue,red)"]),
])
def test_what_stranger6_found_compiled_wrong(text, expected):
    assert meaning(parse(text)) == expected


def test_a_wall_whose_layers_are_listed_unevenly_is_refused():
    with pytest.raises(ParseError, match="different lengths"):
        parse("build a wall, bottom row red blue red, top row blue red")


@pytest.mark.parametrize("text,expected", [
    # stranger6 (eighth session): each had been refused
    ("blue cube -> front left corner", ["in_region(blue,front_left)"]),
    ("ok so here's what i'm thinking \u2014 a little tower, blue on the bottom, then pink, then another blue on top. nothing fancy",
     ["stack(blue,pink,blue)"]),
    ("need a 2x2 grid of blue cubes for the next run", ["grid(2x2:blue,blue,blue,blue)"]),
    ("Pop the cyan cube behind the pink one, cheers.", ["behind(cyan,pink)"]),
    ("I was thinking, could we get the brown block next to the black block? That'd be great for my demo.",
     ["next_to(black,brown)"]),
    ("For the demo: yellow cube on the orange patch, orange cube on the yellow patch.",
     ["on_patch(orange,patch:yellow)", "on_patch(yellow,patch:orange)"]),
    ("put yellow cube in middle", ["in_region(yellow,center)"]),
    ("Build a pyramid in the back-left corner using three green cubes.", ["pyramid(green,green,green)@back_left"]),
])
def test_what_stranger6_found_refused(text, expected):
    assert meaning(parse(text)) == expected


def test_a_starred_per_cube_atom_matches_one_atom_per_cube():
    assert matches("in_region(blue*,front_left)", ["in_region(blue,front_left)", "in_region(blue,front_left)"])
    assert not matches("in_region(blue*,front_left)", ["in_region(blue,front_left)", "in_region(red,front_left)"])


def test_reads_of_a_word_matches_the_reads_atom_of_that_word():
    got = ["line[left_to_right](D,O,G)", "reads(D,O,G;direction=left_to_right,face=up,text=DOG)"]
    assert matches("line[left_to_right](D,O,G); reads(DOG)", got)
    assert not matches("line[left_to_right](D,O,G); reads(GOD)", got)


@pytest.mark.parametrize("text,kind", [
    # found by an attack on the framing words: each compiled with the time, pose or correction dropped
    ("my supervisor wants the red cube on the blue cube, but I want it on the green cube.", "contradiction"),
    ("Put the red cube on the blue cube, but put it on the green cube.", "contradiction"),
    ("Put the red cube on the blue cube for the next run, and for the run after that on the green cube.", "time"),
    ("Initially the blue cube is on the green patch. Put the red cube on the blue cube.", "time"),
    ("Put the red cube on the blue cube at the end, and the blue cube on the green patch at the beginning.", "time"),
    ("The red cube used to be on the blue cube.", "time"),
    ("Success condition: the red cube was on the blue cube.", "time"),
    ("Success condition: the red cube had been on the blue cube.", "time"),
    ("Put the red cube on the blue cube in the morning.", "time"),
    ("For the demo: the red cube lies on its side on the blue cube.", "action"),
    ("Picture the final scene: the red cube rests on its corner on the blue cube.", "action"),
    ("The red cube lies on the green patch, standing on its side.", "action"),
    ("For the demo: the letter A cube on the red patch with the A facing down.", "action"),
    ("Put the red cube left of the blue cube. Colours don't matter.", "contradiction"),
])
def test_times_poses_and_corrections_hidden_among_framing_words_are_refused(text, kind):
    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert kind in {k for k, _, _ in exc.value.reasons}


@pytest.mark.parametrize("text", ["Stack the A cube on the B cube with the letters facing the camera",
                                  "Put the A cube on the red patch with the A facing up"])
def test_a_face_said_of_a_task_whose_goal_judges_no_face_is_refused(text):
    """The face was dropped: the goal only placed the cube."""
    with pytest.raises(ParseError, match="facing"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Spell CAT with the letters facing up", ["line[left_to_right](C,A,T)", "reads(C,A,T;direction=left_to_right,face=up,text=CAT)"]),
    ("Make a line with red at the beginning and blue at the end", ["line(blue,red)"]),  # a place in the line, not a time
    ("Build a tower of three cubes, colours don't matter", ["stack(red,blue,green)"]),  # no colour said: nothing dropped
])
def test_faces_ends_and_free_colours_that_are_read(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    ("Place the yellow block to the right of the purple block, both at the back of the table",
     ["in_region(purple,back)", "in_region(yellow,back)", "right_of(yellow,purple)"]),
    ("Put the red cube next to the blue cube, with both of them on the left side of the table",
     ["in_region(blue,left)", "in_region(red,left)", "next_to(blue,red)"]),
    ("Put the red cube left of the blue cube, the two of them in the back right corner",
     ["in_region(blue,back_right)", "in_region(red,back_right)", "left_of(red,blue)"]),
])
def test_both_cubes_of_a_relation_put_in_a_place(text, expected):
    """"both at the back" had placed the relation's subject alone there (the object dropped)."""
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # "second row" had been read as the top row whatever the height: silently wrong for three or four layers
    ("Build a wall 2 wide and 3 high: the second row blue, the other rows red", ["wall(red,red|blue,blue|red,red)"]),
    ("Build a wall 2 wide and 4 high: first row red, second row blue, third row green, top row white",
     ["wall(red,red|blue,blue|green,green|white,white)"]),
    ("Build a wall 3 wide and 2 high: first layer red, second layer blue", ["wall(red,red,red|blue,blue,blue)"]),
])
def test_a_layer_named_by_its_ordinal_is_that_layer_from_the_table(text, expected):
    assert meaning(parse(text)) == expected


def test_a_layer_ordinal_past_the_structures_height_is_refused():
    with pytest.raises(ParseError, match="no third layer"):
        parse("Build a wall 2 wide and 2 high with the third row blue")


@pytest.mark.parametrize("text,expected", [
    # the stack had been put on the patch and the gray cube dropped from it (stranger7)
    ("Final layout: the pink cube stacked on the orange cube, the gray cube on the white patch, and the black cube far "
     "from the gray cube.", ["far_from(black,gray)", "on_patch(gray,patch:white)", "stack(orange,pink)"]),
    ("Stack the red cube on the blue cube on the green patch", ["on_patch(blue,patch:green)", "stack(blue,red)"]),
    ("Stack the red block on the blue block, then put the yellow block on the green patch",
     ["on_patch(yellow,patch:green)", "stack(blue,red)"]),
])
def test_a_cube_of_no_stack_put_on_a_patch_in_a_stacking_text(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # the label had been dropped: a red cube placed (stranger7)
    ("The cube with the M goes in the center of the table.", ["in_region(M,center)"]),
    ("Bring the cube with the 4 on it to the right front corner.", ["in_region(4,front_right)"]),
    ("Put the cube with an A on the red patch", ["on_patch(A,patch:red)"]),
])
def test_a_cube_named_by_the_label_it_bears(text, expected):
    assert meaning(parse(text)) == expected


def test_letter_side_up_of_a_goal_that_judges_no_face_is_refused():
    with pytest.raises(ParseError, match="letter side up"):
        parse("The cube with the M goes in the center of the table, letter side up.")


@pytest.mark.parametrize("text,expected", [
    # the direction had been dropped: a between and an unordered line (stranger7)
    ("Make a line, from left to right, that starts with the black cube and ends with the white cube, with the gray cube "
     "in the middle.", ["line[left_to_right](black,gray,white)"]),
    ("Make a line from right to left that starts with the black cube and ends with the white cube, with the gray cube "
     "in the middle", ["line[left_to_right](white,gray,black)"]),
    # which corner, said after the corner: it had been any corner
    ("can u put the orange block in the corner? the back left one", ["in_region(orange,back_left)"]),
    ("put the orange block in the corner - the back left one", ["in_region(orange,back_left)"]),
    # a terse line's place with no preposition: it had been a line anywhere
    ("LINE front edge: red, red, red", ["line(red,red,red)@front"]),
])
def test_directions_and_places_said_tersely_or_after_the_fact(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,match", [
    # a direction no part of the goal orders by (the wall judges its layers' colours, not their order in a row)
    ("build a wall: bottom row from left to right red green blue, top row from left to right yellow white pink",
     "'left to right' says which way|lists the cubes in two different orders"),  # (the colour runs read as lists now)
    # a place word no place mention reads and no part of the goal carries
    ("make a row front edge of red, green, blue", "the place 'front'"),
    ("put the red cube next to the blue cube front side", "place word 'front'"),
    ("put the red block on the green patch, corner", "place word 'corner'"),
])
def test_a_direction_or_place_word_the_task_does_not_carry_is_refused(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("In the end, the red block should be on the blue block.", ["stack(blue,red)"]),  # a time, not a place
    ("Make a tower with the two purple cubes right in the middle of the table", ["stack(purple,purple)@center"]),
    ("push left the red block", ["in_region(red,left)"]),
])
def test_place_words_used_for_no_place_or_carried_by_the_goal_are_read(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # each tower's colour said after the count: every tower had been given both colours (stranger7)
    ("i want 2 towers. one is red red. the other one is blue blue", ["stack(blue,blue)", "stack(red,red)"]),
    ("two towers, one red and one blue", ["stack(blue,blue)", "stack(red,red)"]),
    ("two towers of 3 cubes, one red and one blue", ["stack(blue,blue,blue)", "stack(red,red,red)"]),
    ("two towers: red, red and blue, blue", ["stack(blue,blue)", "stack(red,red)"]),
    ("two stacks - the first all red, the second all yellow", ["stack(red,red)", "stack(yellow,yellow)"]),
    # a colour said once per cube with no commas (a transcript): the cubes had collapsed to one per colour
    ("make a line thats blue blue red red going left to right", ["line[left_to_right](blue,blue,red,red)"]),
    ("put the red red block on the blue one", ["stack(blue,red)"]),  # a stutter: one cube
    # a tower's height said as a height: it had been a tower of two
    ("Goal: a tower of height 4 made only of green cubes.", ["stack(green,green,green,green)"]),
    ("a tower with a height of 3 cubes, all red", ["stack(red,red,red)"]),
    # a side of the landmark cube: it had been read as next to
    ("Please help me put green cube to yellow cube left side.", ["left_of(green,yellow)"]),
    ("put the red block to the blue block's right", ["right_of(red,blue)"]),
])
def test_towers_colours_heights_and_sides_said_the_way_people_talk(text, expected):
    assert meaning(parse(text)) == expected


def test_a_tower_given_several_colours_and_no_order_is_refused():
    with pytest.raises(ParseError, match="several colours and not their order"):
        parse("two towers: red, blue and green, yellow")


@pytest.mark.parametrize("text,expected", [
    # letters and digits standing alone on either side of a relation: the middle cube had been dropped,
    # or coloured cubes made up for the letters (stranger7)
    ("STACK 2 on 1, 3 on 2 (digit cubes)", ["stack(1,2,3)"]),
    ("stack the letter cubes: B on A, C on B", ["stack(A,B,C)"]),
    ("stack B on A, C on B", ["stack(A,B,C)"]),
    ("stack letter B on letter A, letter C on letter B", ["stack(A,B,C)"]),
    # a letter said with "should be" before its relation: the sentence's first "A" had been read as an
    # article and dropped silently (stranger7: "A should be on B, B should be on C, ...")
    ("At the end, A should be on B, B should be on C, and C should be on the red patch.",
     ["on_patch(C,patch:red)", "stack(C,B,A)"]),
    ("D goes on B and B should be on C.", ["stack(C,B,D)"]),
    # the reading the cubes must give, said with spaces: it had been the order they were listed in
    ("Put the digit cubes 3, 1 and 2 in a row so that they read 1 2 3 from left to right.",
     ["line[left_to_right](1,2,3)", "reads(1,2,3;direction=left_to_right,face=up,text=123)"]),
    # each role said before its cube: it had made two towers
    ("Make a tower out of three cubes: below red, in the middle blue, above green.", ["stack(red,blue,green)"]),
    ("stack all N blocks", ["stack(red,blue)"]),  # N is a number, not a letter cube
])
def test_labels_readings_and_roles_said_tersely(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,match", [
    ("put the red block on the blue block, then do the same with X", "the letter 'X' has no place"),
    ("Stack the red cube on the blue cube. A should be left.", "the letter 'A' has no place"),
    ("Stack the teal cube on the magenta cube.", "palette does not have"),  # not read as cyan and pink
    ("put the rear cube on the green patch", "current scene"),  # a cube picked by where it stands now
])
def test_letters_colours_and_selectors_the_task_cannot_hold_are_refused(text, match):
    with pytest.raises(BadInput, match=match):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text,expected", [
    ("move the red block to the front of the green patch", ["in_front_of(red,patch:green)"]),
    ("put a red block on the red block", ["stack(red,red)"]),  # two red cubes, not one on itself
    ("pick up the red block with the Franka arm and put it on the blue block", ["stack(blue,red)"]),
    ("using the UR5 robot, stack the red block on the blue block", ["stack(blue,red)"]),
    ("Step 1: put the red block on the blue block. Step 2: put the green block on the red block.",
     ["stack(blue,red,green)"]),
    # in a sequence of placements "the blue block" is the one placed before (IGLU): not a new cube
    ("Place a blue block on top of the blue block. Place two more blue blocks on the blue stack.",
     ["stack(blue,blue,blue,blue)"]),
])
def test_landmarks_tools_and_step_numbers_said_around_the_goal(text, expected):
    assert meaning(parse(text)) == expected


def test_the_robot_named_is_listed_as_dropped_in_the_accounting():
    from rpg.schema.accounting import check_mentions

    record = check_mentions("using the UR5 robot, stack the red block on the blue block",
                            parse("using the UR5 robot, stack the red block on the blue block"))
    assert {"mention": "the ur5 robot", "kind": "ignored",
            "consumed_by": "nothing: no meaning for the goal (reads like 'the effector or robot that does it')"} in record


@pytest.mark.parametrize("text,expected", [
    # a colour after its noun (French, Spanish, Blocksworld): a red cube had been made up for "the cube orange" (stranger8)
    ("Make a tower of two cubes, the cube brown on the cube orange, at the front of the table.", ["stack(orange,brown)@front"]),
    ("Put the cube green to the right of the cube red and the cube blue to the left of the cube red.",
     ["left_of(blue,red)", "right_of(green,red)"]),
    ("The goal is to have block purple on block yellow.", ["stack(yellow,purple)"]),
    ("Place the cube of colour blue at the left of the cube yellow.", ["left_of(blue,yellow)"]),
    # headings, cheering and pet names around the task
    ("First lesson, stacking: put the yellow cube on the green cube.", ["stack(green,yellow)"]),
    ("Side quest, The Lost Letter: place the Q cube on the purple patch.", ["on_patch(Q,patch:purple)"]),
    ("Okay sweetie, red block goes on the blue block. Red on blue! Yay!", ["stack(blue,red)"]),
    ("Right then, pop the orange cube in the centre of the table, there's a good chap.", ["in_region(orange,center)"]),
    # the sort by the up faces is not added to a line of listed digits (faces unsaid)
    ("Arrange the cubes 4, 2, 5, 1, 3 in ascending order from left to right.", ["line[left_to_right](1,2,3,4,5)"]),
])
def test_colours_after_nouns_headings_cheers_and_sorts_of_listed_labels(text, expected):
    assert meaning(parse(text)) == expected


def test_a_sentence_that_is_not_only_cheering_is_still_read():
    with pytest.raises(ParseError, match="turns around"):
        parse("Put red on blue. Then flip it.")


@pytest.mark.parametrize("text,expected", [
    # a config's keys and values (stranger8): the height had been dropped (a tower of two)
    ('{"task": "tower", "height": 3, "color": "cyan"}', ["stack(cyan,cyan,cyan)"]),
    ('{"instruction": "build a tower of four cubes: green, green, blue, blue from the bottom up", "seed": 7}',
     ["stack(green,green,blue,blue)"]),
    # a table row's and a list's separators: the circle had six cubes, the roles swapped
    ("objective: circle | cubes: red / white / red / white", ["circle(red,red,white,white)"]),
    ("tower | top: pink | bottom: gray", ["stack(gray,pink)"]),
])
def test_configs_and_table_rows(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,match", [
    ('{"task": "stack", "objects": ["blue_large", "red_small"]}', "size"),  # "blue_large" is a size
    ("Should there be a letter cube A, place it behind the B cube.", "conditional"),  # an inverted 'if'
])
def test_sizes_in_object_names_and_inverted_conditions_are_refused(text, match):
    with pytest.raises(BadInput, match=match):
        parse(text)


def test_a_pyramids_layers_said_as_the_bottom_three_and_the_next_two():
    """The counts had been dropped: a pyramid of three (stranger6)."""
    assert meaning(parse("Build a 3-2-1 pyramid: the bottom three are yellow, the next two are orange, the top one is red.")) \
        == ["pyramid(yellow,yellow,yellow|orange,orange|red)"]


def test_so_they_read_a_word_cites_the_line_and_its_order():
    """"so they read KATE" demands a line in that order; the compile had refused it as demanding what no word says."""
    from rpg.schema.citations import unstated

    schema = parse("arrange the letter blocks K, A, T, E so they read KATE")
    assert unstated(schema, schema.instruction) == []


@pytest.mark.parametrize("text", ["put 2 letter cubes on the red patch", "put two digit cubes on the blue patch"])
def test_labelled_cubes_read_as_coloured_ones_are_refused(text):
    """The patch reader had put two coloured cubes on the patch, silently."""
    with pytest.raises(ParseError, match="names labelled cubes"):
        parse(text)


def test_a_colour_list_without_commas_keeps_every_cube():
    """Found by an attack: "red blue red blue" had collapsed to two cubes (only a colour said twice in a row split)."""
    assert meaning(parse("make a line of red blue red blue")) == ["line[sequence](red,blue,red,blue)"]


def test_a_nested_config_is_refused_not_guessed():
    """Found by an attack: a nested dict had become a tower of two invented colours, its height dropped."""
    with pytest.raises(ParseError, match="nested config"):
        parse("{'task': {'a': {'b': 'tower'}}, 'height': [[3]]}")


@pytest.mark.parametrize("text,expected", [
    # a label before its colon that names nothing of the task (stranger8): 'obj', 'req', 'cfg' were unknown words
    ("Obj: red on blue. Conf: stack, 2 high.", ["stack(blue,red)"]),
    ("cfg: orange behind purple", ["behind(orange,purple)"]),
    ("Checklist: \u2022 orange cube on the gray patch \u2022 black cube behind the orange cube",
     ["behind(black,orange)", "on_patch(orange,patch:gray)"]),
    ("Objective (bonus stage): line up three green cubes along the front edge of the table.", ["line(green,green,green)@front"]),
    # a count written as a multiplier: "3x white" had been read as a tower of two
    ("Req: 3x white, towered.", ["stack(white,white,white)"]),
    ("stack white x3", ["stack(white,white,white)"]),
    ("put 3 white in a row", ["line(white,white,white)"]),  # a line of four had been refused
    ("RING: 3 red 3 white", ["circle(red,red,red,white,white,white)"]),
    ("Pyramid at the back: four purple cubes at the bottom, then three, then two, then one, all purple.",
     ["pyramid(purple,purple,purple,purple|purple,purple,purple|purple,purple|purple)@back"]),
])
def test_labels_before_a_colon_and_counts_as_multipliers(text, expected):
    assert meaning(parse(text)) == expected


def test_a_label_that_says_what_the_domain_cannot_is_still_refused():
    with pytest.raises(Inexpressible, match="negation"):
        parse("Never: put red on blue.")


def test_a_dropped_label_is_listed_in_the_accounting():
    from rpg.schema.accounting import check_mentions

    rows = check_mentions("Obj: red on blue.", parse("Obj: red on blue."))
    assert {"mention": "obj", "kind": "ignored", "consumed_by": "nothing: no meaning for the goal (reads like 'a label "
            "before its colon')"} in rows


@pytest.mark.parametrize("text", ["line 1 2 3", "stack 1 2", "stack 2 on 1", "line 3 5", "a tower, height 3"])
def test_a_digit_that_is_neither_a_digit_cube_nor_a_count_is_refused(text):
    """"line 1 2 3" had compiled to a line of four coloured cubes, "stack 2 on 1" to red under blue (silently)."""
    with pytest.raises(ParseError, match="neither a digit cube nor a count|may name digit cubes or count cubes"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # Markdown around the words (stranger9): "the **blue** patch" had become a blue cube under the red one, silently
    ("## Goal The `red` cube goes on the **blue** patch.", ["on_patch(red,patch:blue)"]),
    ("- [ ] stack *red* on blue", ["stack(blue,red)"]),
    ("~~Put the red cube on the left.~~ Put the red cube on the right.", ["in_region(red,right)"]),  # struck out: withdrawn
    # rows written as a product: a wall of four had been read
    ("`wall`: 2 rows x 3 cubes, all grey", ["wall(gray,gray,gray,gray,gray,gray)"]),
    # a range with a hyphen: the digit 0 had been dropped
    ("The agent must arrange the digit cubes 0-4 in ascending order from left to right.", ["line[left_to_right](0,1,2,3,4)"]),
    # "the cube the blue" (Italian, Arabic): a yellow cube had been made up for "the cube"
    ("And put the cube the blue on the cube the red, and put the cube the green on the cube the blue.", ["stack(red,blue,green)"]),
])
def test_markdown_products_ranges_and_articles_before_colours(text, expected):
    assert meaning(parse(text)) == expected


def test_more_cubes_of_a_colour_add_to_those_counted_before():
    """"three blue cubes ... three more blue cubes" is six: a wall of four had been read, silently."""
    with pytest.raises(ParseError, match="asks for 6 blue cubes"):
        parse("Step 1: lay out three blue cubes side by side. Step 2: lay three more blue cubes on top of them. That is your wall.")


@pytest.mark.parametrize("text,expected", [
    # texting (stranger9): abbreviations, "2" for "to", "blk" read by the word after it
    ("cn u put blk cube nxt 2 brwn cube", ["next_to(black,brown)"]),
    ("grn on ylw, then red on grn. thx!!", ["stack(yellow,green,red)"]),
    ("move the green cube 2 the back pls", ["in_region(green,back)"]),
    ("Set: gray blk between black & white blks.", ["between(gray;black,white)"]),
    ("yo pls put the 4 cube btwn the 1 & 9 cubes", ["between(4;1,9)"]),
    ("The robot shall place the red cube upon the blue patch.", ["on_patch(red,patch:blue)"]),
    # chat transcripts: timestamps and speakers
    ("[10:32] alice: stack blue on green [10:33] bob: ok on it", ["stack(green,blue)"]),
    ("<dana> can u build a 3-tower: brown, then red, then yellow on top", ["stack(brown,red,yellow)"]),
    ("alice> blue cube in front of the red cube pls", ["in_front_of(blue,red)"]),
    # a paper's, a benchmark's or an annotator's framing of the goal
    ("In this task the agent must stack the green cube on top of the red cube. The episode is successful if the green "
     "cube rests on the red cube.", ["stack(red,green)"]),
    ('"""The episode succeeds if the pink cube sits between the two black cubes."""', ["between(pink;black,black)"]),
    ("# success := blue cube anywhere inside the back-left corner", ["in_region(blue,back_left)"]),
    ("The agent must build a 3-2-1 pyramid from six green cubes. Success is judged on the final configuration only.",
     ["pyramid(green,green,green,green,green,green)"]),
    ("In the final image, the blue cube is sitting on top of the yellow cube.", ["stack(yellow,blue)"]),
    ("Before: cubes scattered. After: the three grey cubes are lined up in a row.", ["line(gray,gray,gray)"]),
])
def test_texting_chat_transcripts_and_a_papers_framing_of_the_goal(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,match", [
    ("If the red cube is on the blue patch, stack the green cube on it.", "conditional"),  # a condition stays one
    ("The episode is successful if the red cube is not on the blue cube.", "negation"),
    ("Put the red cube where it is in the image.", "image|shown"),
])
def test_framing_words_drop_only_the_frame(text, match):
    with pytest.raises(BadInput, match=match):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a writer correcting themselves (stranger9): the correction replaces what it corrects
    ("Put the green cube on the yellow patch, sorry, the pink patch.", ["on_patch(green,patch:pink)"]),
    ("Stack red on blue, I mean blue on red.", ["stack(red,blue)"]),
    ("Move the black cube to the left, er no, to the front.", ["in_region(black,front)"]),
    ("Make a row of three grey cubes, sorry, four grey cubes.", ["line(gray,gray,gray,gray)"]),
    ("Put the 3 cube next to the 5 cube, I mean the 6 cube.", ["next_to(3,6)"]),
    ("Put the grey cube on the lavender patch, I mean the grey patch.", ["on_patch(gray,patch:gray)"]),
    ("[09:14] sam: put the pink cube on the blue patch [09:15] sam: wait no, the green patch", ["on_patch(pink,patch:green)"]),
    ("put the red cube on the blue cube, sorry, I mean the green cube", ["stack(green,red)"]),
])
def test_a_self_correction_replaces_what_it_corrects(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "stack red on blue, sorry, I mean green",  # red or blue?
    "Put the blue cube on the green cube, I mean under it, er no, on it after all.",  # 'it' after a replacement
    "Build a tower of yellow on brown, er no, just put them side by side.",
])
def test_a_correction_whose_target_is_unclear_is_refused(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # Markdown quotes and headings flattened onto their text, emoji, shouting (stranger9)
    ("> **Note:** the brown cube must end up *far from* the pink cube.", ["far_from(brown,pink)"]),
    ("## Task Stack **green** on **red**.", ["stack(red,green)"]),
    ("Me: make a line of four black cubes at the back. Them: \U0001F44D", ["line(black,black,black,black)@back"]),
    ("omg \U0001F60D put the blue cube next to the black cube pleeease!!!", ["next_to(black,blue)"]),
    ("PUT THE 7 CUBE ON THE 2 CUBE!!!!", ["stack(2,7)"]),
    ("SPELL CAT WITH THE LETTER CUBES", ["line[left_to_right](C,A,T)", "reads(C,A,T;direction=left_to_right,face=up,text=CAT)"]),
    # an exam's and a rubric's framing
    ("Q4. Put the letter cubes in order so they read A B C from left to right. (2 marks)",
     ["line[left_to_right](A,B,C)", "reads(A,B,C;direction=left_to_right,face=up,text=ABC)"]),
    ("Rubric: full marks if the yellow cube ends to the right of the black cube; zero otherwise.", ["right_of(yellow,black)"]),
    ("Grader note: accept any answer where the two pink cubes form a stack.", ["stack(pink,pink)"]),
    ("Rubric item 2: the wall has red cubes on the bottom row (3) and yellow cubes on the top row (3).",
     ["wall(red,red,red|yellow,yellow,yellow)"]),
    # interjections of other languages' habits, "the patch the green", "how you prefer"
    ("Allora, the cube black, you put it in the middle of the table, va bene?", ["in_region(black,center)"]),
    ("Put the cube the yellow on the patch the green.", ["on_patch(yellow,patch:green)"]),
    ("Make a tower with the cube green and the cube yellow, how you prefer.", ["stack(green,yellow)"]),
    # a contract's register
    ("The green cube shall be deposited upon the yellow cube, and the black cube shall in turn be deposited upon the "
     "aforementioned green cube.", ["stack(yellow,green,black)"]),
    ("It is hereby agreed that the three brown cubes shall be arranged in a single row along the front of the table.",
     ["line(brown,brown,brown)@front"]),
    ("Forthwith, the robot shall assemble a circle comprising four (4) pink cubes.", ["circle(pink,pink,pink,pink)"]),
])
def test_markdown_emoji_shouting_rubrics_and_registers(text, expected):
    assert meaning(parse(text)) == expected


def test_a_shouted_negation_is_still_refused():
    with pytest.raises(Inexpressible, match="negation"):
        parse("DO NOT PUT THE RED CUBE ON THE BLUE CUBE!!!")


@pytest.mark.parametrize("text,expected", [
    # a start stated with the goal: rho_0's stacks, the goal read by the whole front end
    ("Initially the red cube is on the blue cube. Put the red cube on the green patch.",
     ["on_patch(red,patch:green); start:stack(blue,red)"]),
    ("Start: a tower of red, green, blue. Goal: build a tower of blue, green, red.",
     ["stack(blue,green,red); start:stack(red,green,blue)"]),
    ("Start: a tower of red, green, blue (top to bottom). Goal: red on the table.",
     ["on_table(red); start:stack(blue,green,red)"]),
    ("At the start, red is on blue and green is on yellow. Stack all four into one tower: yellow, green, blue, red.",
     ["stack(yellow,green,blue,red); start:stack(blue,red); start:stack(yellow,green)"]),
    ("Initial state: the blue cube sits on the red cube, the rest scattered. Put the green cube next to the red cube.",
     ["next_to(green,red); start:stack(red,blue)"]),
    ("The pink cube starts stacked on the grey cube and must end up on the table.", ["on_table(pink); start:stack(gray,pink)"]),
    ("# goal (unstack): the pink cube starts stacked on the grey cube and must finish on the table",
     ["on_table(pink); start:stack(gray,pink)"]),
    ("The red cube starts on the blue cube. Put it next to the green cube.", ["next_to(green,red); start:stack(blue,red)"]),
    ("Setup: red on blue on green. Goal: red on the table.", ["on_table(red); start:stack(green,blue,red)"]),
])
def test_an_initial_scene_stated_with_the_goal(text, expected):
    assert meaning(check_feasibility(parse(text))) in [expected, [e for x in expected for e in x.split("; ")]]


@pytest.mark.parametrize("text", [
    "Initially the red cube is on the blue cube and the blue cube is on the red cube. Put the green cube on the red cube.",
    "Initially red is on red. Put the blue cube on the red cube.",
    "Initially the gripper holds the red cube. Put the red cube on the blue cube.",  # the domain has no held cube
    "Initially the red cube is on the blue cube.",  # no goal
    "stack red on blue on green. red on the table.",  # the goal stacks red and sends it to the table: a silent error before
])
def test_a_start_that_cannot_be_built_or_a_goal_at_odds_with_itself_is_refused(text):
    with pytest.raises(BadInput):
        parse(text)


def test_a_start_compiles_and_places_its_stacks(tmp_path):
    """End to end: rho_0 starts both stacks (the compile's validation gates pass)."""
    import yaml

    from rpg.compiler import compile_instruction

    r = compile_instruction("At the start, red is on blue and green is on yellow. Stack all four into one tower: yellow, "
                            "green, blue, red.", tmp_path)
    assert r.valid, [g for g in r.gates if g["status"] == "fail"]
    task = yaml.safe_load((r.path / "task.yaml").read_text())
    assert task["schema"]["initial_state"]["structures"] == [["blue", "red"], ["yellow", "green"]]


@pytest.mark.parametrize("text,goal,start", [
    # Blocksworld's start (letter blocks, 'on the table', 'clear', an empty hand), then its goal
    ("Initial state: A is on B, B is on the table, C is on the table, A is clear, C is clear, the hand is empty. Goal: C on A.",
     "On(a='letter_c', b='letter_a')", [["letter_b", "letter_a"]]),
    ("Initially block A is on block B. Put block B on block C.", "Stack(objects=['letter_c', 'letter_b'])",
     [["letter_b", "letter_a"]]),
    # a goal on a cube that starts on another does not also send that cube to the table
    ("Start: red on blue. Goal: put green on red.", "On(a='green', b='red')", [["blue", "red"]]),
])
def test_a_blocksworld_start_and_a_goal_on_a_raised_cube(text, goal, start):
    schema = check_feasibility(parse(text))
    assert repr(schema.goal) == goal and schema.initial_state.structures == start


def test_a_clear_cube_with_a_cube_on_it_is_not_read_as_a_start():
    with pytest.raises(BadInput):
        parse("Initially: A on B, B is clear. Goal: C on A.")


@pytest.mark.parametrize("text,expected", [
    # the verb last and the places postposed (Japanese, Korean, Turkish habits; stranger8, stranger9)
    ("The 4 cube, the 2 cube's top on, stacking please.", ["stack(2,4)"]),
    ("As for the green cube, the yellow patch on, please put.", ["on_patch(green,patch:yellow)"]),
    ("Pink cube's right side to, cyan cube please put.", ["right_of(cyan,pink)"]),
    ("Table's right-front corner, white cube, please put.", ["in_region(white,front_right)"]),
])
def test_an_instruction_with_its_verb_last(text, expected):
    assert meaning(parse(text)) == expected


def test_a_negated_instruction_with_its_verb_last_is_refused_as_written():
    with pytest.raises(Inexpressible, match="negation"):
        parse("Red cube, blue cube's top on, do not put please.")


def test_a_word_read_from_the_bottom_up_puts_its_first_letter_at_the_bottom():
    """"so they read D, O, G from bottom to top" had stacked G at the bottom (steer_stranger6's base)."""
    schema = parse("Stack the letter cubes so they read D, O, G from bottom to top")
    assert meaning(schema) == ["reads(D,O,G;direction=bottom_to_top,face=front,text=DOG)", "stack(D,O,G)"]


@pytest.mark.parametrize("text", [
    "stack white, white, then black, black on top",  # had compiled to a tower of three (a black cube dropped)
])
def test_each_colour_of_a_list_is_a_cube_of_the_task(text):
    with pytest.raises(ParseError, match="lists 2 black cubes"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Goal: blue on red, red on yellow.", ["stack(yellow,red,blue)"]),  # a chain's pairs are no list of colours
    ("red left of blue, blue left of green", ["left_of(blue,green)", "left_of(red,blue)"]),
])
def test_the_pairs_of_a_chain_are_not_a_list(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "Start: a tower of red, blue, red, blue. Goal: red on the table.",  # had compiled to a tower of five, the goal dropped
    "Initial state: A is on B, A is on C. Goal: C on A.",  # had compiled to a tower of A, C, B
])
def test_a_stated_start_that_cannot_be_built_is_refused_not_read_as_the_goal(text):
    with pytest.raises(Inexpressible, match="starting scene rpg does not build"):
        parse(text)


def test_a_scattered_start_is_every_tasks_start():
    schema = parse("At the start, everything is scattered. Build a tower of red and blue.")
    assert schema.initial_state.structures == [] and meaning(schema) == ["stack(red,blue)"]


@pytest.mark.parametrize("text,expected", [
    ("stack U on V", ["stack(V,U)"]),  # a capital U is a letter cube (texting's lower-case "u" is "you")
    ("Tgt: pink -> blue patch. brown -> blue patch.", ["on_patch(brown,pink,patch:blue)"]),  # a cube sent to a patch by an arrow
])
def test_letter_u_and_arrows_to_patches(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a paper's, a code comment's and an exam's framing (stranger9)
    ("We evaluate a tower-building task in which the policy must build a four-block tower of alternating red and blue "
     "cubes, with red at the base.", ["stack(red,blue,red,blue)"]),
    ('"""Place the letter cubes so they spell DOG when read from left to right."""',
     ["line[left_to_right](D,O,G)", "reads(D,O,G;direction=left_to_right,face=up,text=DOG)"]),
    ("# check: brown cube is left of green cube  (see test_relations.py)", ["left_of(brown,green)"]),
    ('def build_tower():  """Build a tower: black at the base, brown in the middle, grey on top."""', ["stack(black,brown,gray)"]),
    ("# NOTE: digit cubes 4 2 1 3 must end up sorted ascending, left to right", ["line[left_to_right](1,2,3,4)"]),
    ("Episode success: the pink cube is placed within the front-left quadrant of the workspace.", ["in_region(pink,front_left)"]),
    ("In this task the agent must place the brown cube behind the yellow cube. Success requires no particular orientation.",
     ["behind(brown,yellow)"]),
    ("Compared with the first picture, the pink cube now sits between the two brown cubes.", ["between(pink;brown,brown)"]),
    ("Q3. (4 points) Write a plan so that the blue cube ends on the green patch.", ["on_patch(blue,patch:green)"]),
])
def test_more_framings_of_a_goal(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "a row that ends with red",  # had compiled to a line of four red cubes
    "a row of red, blue and green that ends with red",  # had compiled to an unordered line
])
def test_a_cube_given_an_end_of_a_sequence_the_goal_does_not_order_is_refused(text):
    with pytest.raises(ParseError, match="place at one end|row's middle"):  # (the middle, dropped with the end, is checked first)
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a sort asked of listed labels (stranger10): the listed order had been kept, silently
    ("Sort the digit cubes 4, 9 and 2 from front to back, smallest in front.", ["line[front_to_back](2,4,9)"]),
    ("Sort the digit cubes 4, 9 and 2 from left to right", ["line[left_to_right](2,4,9)"]),
    ("Stack the cubes labelled 7, 3 and 5 in ascending order, smallest at the bottom.", ["stack(3,5,7)"]),
    ("Stack the digit cubes 7, 3 and 5 in descending order", ["stack(7,5,3)"]),
    ("Arrange the letter cubes A, B, C, D in reverse alphabetical order from left to right", ["line[left_to_right](D,C,B,A)"]),
    # a wall's layers said by colour and its width per layer: its bottom cube alone had been blue, the rest invented
    ("The robot should build a two-layer wall with blue on the bottom and green on the top, three cubes per layer, at the back "
     "of the table.", ["wall(blue,blue,blue|green,green,green)@back"]),
    ("a wall of two layers, three cubes each, blue at the bottom and green on top", ["wall(blue,blue,blue|green,green,green)"]),
])
def test_sorted_labels_and_a_walls_layers_by_colour(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a user story, an email and a request around the task (stranger10)
    ("As a tester, I want the robot to place the purple cube on the green patch, so that I can check basic placement.",
     ["on_patch(purple,patch:green)"]),
    ("As an evaluator I want the two pink cubes to end up next to each other, so the adjacency check gets exercised.",
     ["next_to(pink,pink)"]),
    ("Hi Sam, for tomorrow's run could you set up the task where the black cube goes on top of the white cube? Thanks, Priya",
     ["stack(white,black)"]),
    ("Dear Ana, please make the task with all four yellow cubes in a row along the back. Best, Marek",
     ["line(yellow,yellow,yellow,yellow)@back"]),
])
def test_a_user_story_an_email_and_a_request_around_the_task(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a task's identifier before its text (stranger11): each had been refused over 'task', 'relation', 'g-'...
    ("Task 7 (Stacking-3): the agent must build a three-cube tower with green at the bottom, white in the middle and black "
     "on top.", ["stack(green,white,black)"]),
    ("Relation test R-3: orange in front of the brown cube.", ["in_front_of(orange,brown)"]),
    ("Generalisation split G-4: tower of three, colours bottom-to-top pink, cyan, pink.", ["stack(pink,cyan,pink)"]),
    # the label's structure word, where the text names none
    ("Task 12 (Line-Sort-Colour): red, orange, yellow, green, blue, left to right.",
     ["line[left_to_right](red,orange,yellow,green,blue)"]),
    ("stack-3: bottom-to-top order blue, yellow, red", ["stack(blue,yellow,red)"]),  # it had been a line
    ("Unstack-2. init: orange on top of purple. goal: orange on the table next to purple.",  # (on the table: said)
     ["next_to(orange,purple)", "on_table(orange)", "start:stack(purple,orange)"]),
    # the start said without its subject, or as "Scene init:" (the first had put the start's stack in the goal)
    ("Task 60 (Unstack-Relate): starts with the yellow cube on the red cube; at the end the yellow cube is behind the red "
     "cube.", ["behind(yellow,red)", "start:stack(red,yellow)"]),
    ("Scene init: cubes scattered. Goal: the white cube sits between the two black cubes.", ["between(white;black,black)"]),
    # a colour or a place after its noun (Spanish): 'the cube cyan' had become a red cube
    ("Put the cube pink in front of the cube cyan, and the cube white behind of the cube cyan.",
     ["behind(white,cyan)", "in_front_of(pink,cyan)"]),
    ("Please put the cube yellow on the patch blue.", ["on_patch(yellow,patch:blue)"]),
    ("Put the cube black in the corner back right.", ["in_region(black,back_right)"]),
])
def test_an_identifier_label_a_start_without_subject_and_a_colour_after_its_noun(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,why", [
    ("Time-limited stacking: red on blue.", "time-limited"),  # a label that says what the domain cannot is read, and refused
    ("Shape-8: eight cubes forming a hollow square outline.", "hollow"),
    ("bottom-to-top order blue, yellow, red", "could not find a task"),  # a tower's order, never a line
])
def test_a_label_that_says_more_than_an_identifier_is_not_dropped(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


def test_a_label_saying_any_order_leaves_the_tower_unordered():
    """"Stack-any-order: ..." had demanded an order of the tower no word says."""
    from rpg.domain.predicates import UnorderedStack

    schema = parse("Stack-any-order: build a single tower from the red, yellow and blue cubes; order does not matter.")
    assert [type(p) for p in schema.goal_predicate().walk() if type(p).__name__.endswith("Stack")] == [UnorderedStack]


@pytest.mark.parametrize("text,expected", [
    # a speech-to-text transcript (stranger11): hesitations, words said twice, corrections without a pause
    ("uh so put the the orange cube on the uh purple patch no I mean the pink patch", ["on_patch(orange,patch:pink)"]),
    ("can you uh stack stack the yellow cube on the the orange no the purple cube", ["stack(purple,yellow)"]),
    ("put the cyan cube in the uh in the front no the back of the table", ["in_region(cyan,back)"]),
    ("okay put the the green cube um behind the the blue cube yeah behind it", ["behind(green,blue)"]),
    ("put the blue the blue cube on top of the red and then and then the red one goes next to the no on top of the green",
     ["stack(green,red,blue)"]),
    ("make a uh a wall I mean a a row of white cubes three of them", ["line(white,white,white)"]),  # it had been a row of four
    ("uh okay um line up the the letter cubes to say uh D O G dog from left to right",
     ["line[left_to_right](D,O,G)", "reads(D,O,G;direction=left_to_right,face=up,text=DOG)"]),
    # what the rules must leave alone: two cubes of a colour, a correction after a hesitation, a subset's count
    ("two towers! one blue blue and one pink pink", ["stack(blue,blue)", "stack(pink,pink)"]),
    ("put the red cube to the left, er no, to the front", ["in_region(red,front)"]),
    ("Form a circle with four cubes, two of them blacks and two whites.", ["circle(black,black,white,white)"]),
])
def test_a_spoken_transcript_is_read_as_meant(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,why", [
    ("put no cubes on the patch", "negation"),  # "no" before a noun stays a negation, not a correction
    ("Ingredients: 2 cubes. Method: build a tower three cubes tall.", "says the task has 2 cubes"),
])
def test_a_negation_stays_and_a_counted_inventory_must_match(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a task written as a config: key=value pairs, bullets, a flat dict after a label (stranger11, stranger8)
    ("structure=line; n=5; colour=green; region=back", ["line(green,green,green,green,green)@back"]),
    ("- cubes: 4 x blue - structure: tower - location: front right corner", ["stack(blue,blue,blue,blue)@front_right"]),
    ('Goal spec: {"relation": "between", "target": "white", "anchors": ["black", "brown"]}', ["between(white;black,brown)"]),
    ('The episode is defined as {"task": "place", "object": "brown cube", "target": "patch", "target_colour": "orange"}.',
     ["on_patch(brown,patch:orange)"]),
    ("config: {structure: line, direction: front_to_back, cubes: [red, green, blue]}", ["line[front_to_back](red,green,blue)"]),
    ("obj=stack; cubes=gray,gray,black; bottom_first=yes", ["stack(gray,gray,black)"]),
    ('{"goal": "on_patch", "cube": "orange", "patch": "green"}', ["on_patch(orange,patch:green)"]),
])
def test_a_task_written_as_a_config(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,why", [
    ('{"goal": "far_from", "a": "red", "b": "blue", "min_dist_m": 0.3}', "min"),  # a key of no known role: not guessed
    ('{"task": "stack", "objects": ["blue_large", "red_small"]}', "size"),  # a value read as a sentence would be
    ('{"task": "stack", "constraint": "never put black on white"}', "negation"),
    ("time: 10 s, goal: red on blue", "about time"),  # "10 s" had been dropped with its label
    ("structure=line; n=5; colour=red; region=nowhere", "structure"),  # a place of no region: it had been dropped
    ("stack red on blue in under 2 min", "about time"),
])
def test_a_config_says_nothing_the_domain_cannot_and_a_time_limit_is_refused(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a tower said by its ends with steps between (no word 'tower'): the middle cube had been dropped
    ("purple on the bottom then pink then white on top", ["stack(purple,pink,white)"]),
    # a wish for a placement, continued by "then ... on top"
    ("i want the red one on the blue one and then the green one on top", ["stack(blue,red,green)"]),
    # "in the middle of the two red ones" is between them
    ("the yellow one goes in the middle of the two red ones", ["between(yellow;red,red)"]),
    # Indian English: "keep" puts a cube somewhere, "do one thing" opens a request, "itself" stresses
    ("Do one thing, keep the green cube on top of the red cube only.", ["stack(red,green)"]),
    ("Do one thing, put the red cube and blue cube both on the yellow patch itself.", ["on_patch(blue,red,patch:yellow)"]),
    ("Task 22 (Two-Relations): blue next to red; green far from red.", ["far_from(green,red)", "next_to(blue,red)"]),
    ("About the tower: bottom is blue, top is red, middle is green. Please do.", ["stack(blue,green,red)"]),
])
def test_a_tower_by_its_ends_a_wish_between_two_and_indian_english(text, expected):
    assert meaning(parse(text)) == expected


def test_a_tower_with_one_colour_said_once_invents_no_second_cube():
    """"a tower, red at the bottom" had been a tower of two red cubes."""
    with pytest.raises(ParseError):
        parse("a tower, red at the bottom")
    assert meaning(parse("stack the red blocks")) == ["stack(red,red)"]


@pytest.mark.parametrize("text,expected", [
    # the order read, said digit by digit, wins over an order said before it (it had built the row 3, 1, 2)
    ("The cubes are in the order 3, 1, 2. Rearrange them into a row that reads 1 2 3 from left to right.",
     ["line[left_to_right](1,2,3)", "reads(1,2,3;direction=left_to_right,face=up,text=123)"]),
    ("Put the letter cubes T, A, C in a row so they read C A T from left to right",
     ["line[left_to_right](C,A,T)", "reads(C,A,T;direction=left_to_right,face=up,text=CAT)"]),
    ("rearrange the red, green and blue cubes into a line", ["line(blue,green,red)"]),  # 'rearrange' had been an action
])
def test_the_order_read_wins_and_rearrange_arranges(text, expected):
    assert meaning(parse(text)) == expected


def test_a_start_of_digit_cubes_in_a_row_is_refused_not_read_as_the_goal():
    with pytest.raises(BadInput, match="starting scene"):
        parse("The digit cubes start in the order 3, 1, 2. The policy has to rearrange them into a row that reads 1 2 3 "
              "from left to right.")


@pytest.mark.parametrize("text,expected", [
    # stranger12: an opposite denied restates the relation; "stays" on the table; a pyramid said by its two layers
    ("Put the black cube in front of the grey cube, not behind it.", ["in_front_of(black,gray)"]),
    ("put the red cube on top of the blue cube, not below it", ["stack(blue,red)"]),
    ("Put the red cube on the blue cube. The blue cube stays on the table.", ["stack(blue,red)"]),
    ("Pyramid: an orange and a pink cube side by side, and a white cube resting on both.", ["pyramid(orange,pink|white)"]),
])
def test_an_opposite_denied_a_cube_that_stays_and_a_pyramid_by_its_layers(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,why", [
    ("put the red cube left of the blue cube, not next to it", "negation"),  # a denial that adds a constraint stays
    ("Put the red cube on the green one, like before.", "like before"),  # an earlier turn
])
def test_a_denial_that_adds_an_earlier_turn_and_named_digits_are_not_guessed(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


@pytest.mark.parametrize("text", [
    "Task 7 (x): " * 10000,  # labels within labels: it had recursed until Python's limit (30 s, a RecursionError)
    "no I mean the " * 10000,  # thousands of spoken corrections: they had taken minutes to rewrite
])
def test_a_huge_text_is_refused_before_it_is_rewritten(text):
    with pytest.raises(ParseError, match="the limit is"):
        parse(text)


def test_one_frame_is_read_never_a_frame_inside_it():
    with pytest.raises(BadInput):
        parse("Task 7 (Stacking-3): Task 8 (x): stack red on blue")  # the inner label is read as words, and refused


@pytest.mark.parametrize("text,expected", [
    # stranger13's silent errors: "both" and "next to each other" make the pair the subject of what follows
    ("Place the blue cube next to the red cube, both on the white patch.",
     ["next_to(blue,red)", "on_patch(blue,red,patch:white)"]),
    ("Put the blue cube next to the red cube, and put them both on the green patch.",
     ["next_to(blue,red)", "on_patch(blue,red,patch:green)"]),
    ("Put the blue cube and the red cube next to each other in front of the green cube.",
     ["in_front_of(blue,green)", "in_front_of(red,green)", "next_to(blue,red)"]),
    ("set up: grey cube left of black cube, both in the back",
     ["in_region(black,back)", "in_region(gray,back)", "left_of(gray,black)"]),
    ("put the red cube left of the blue cube and the green cube behind them",
     ["behind(green,blue)", "behind(green,red)", "left_of(red,blue)"]),
    # a role word before a dash is a label, not a relation (it had invented a red cube under the black one)
    ("Build tower from three cubes: below - black, in middle - gray, above - white.", ["stack(black,gray,white)"]),
    # one pile is written pile(...), its place with it
    ("digit cubes 5, 2, 8 in a row, small to big", ["line[left_to_right](2,5,8)"]),  # the sort had been dropped
    ("Pile the three orange cubes up in the center.", ["pile(orange,orange,orange)@center"]),
])
def test_a_pair_said_together_gets_every_relation_and_a_role_label_is_no_relation(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,why", [
    ("put the red cube left of the blue cube and the green cube on them", "two cubes at once"),  # it had been on blue
    ("put the red cube next to the blue cube, both on the green cube", "cannot all be on one cube"),
])
def test_one_cube_on_a_pair_is_refused(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


def test_a_pyramid_layer_count_is_not_a_pair():  # "2 in the middle" is not "both" (numbers are normalized)
    assert meaning(parse("Make a pyramid with 3 blocks on the bottom, 2 in the middle and 1 on top")) == \
        ["pyramid(red,red,red,red,red,red)"]


@pytest.mark.parametrize("text,expected", [
    # stranger13's ordinary voices: who is addressed, a QA's expected result, a side with "side", a direction with articles
    ("Okay friends, can everyone put the red block on top of the blue block? Good job!", ["stack(blue,red)"]),
    ("Boys and girls, put the purple block next to the orange block, nice and close.", ["next_to(orange,purple)"]),
    ("Expected result - purple cube on the orange patch, orange cube on the purple patch.",
     ["on_patch(orange,patch:purple)", "on_patch(purple,patch:orange)"]),
    ("Line up the cyan, pink and brown cubes along the left side.", ["line(brown,cyan,pink)@left"]),
    ("Make a line of 3 cyan cubes on the left side.", ["line(cyan,cyan,cyan)@left"]),
    ("Make a line of the cubes purple, pink and cyan, from the left to the right.", ["line[left_to_right](purple,pink,cyan)"]),
])
def test_an_audience_an_expected_result_and_a_side_of_the_table(text, expected):
    assert meaning(parse(text)) == expected


def test_a_side_after_a_relation_stays_relative():
    with pytest.raises(BadInput, match="no part"):  # the left side of the table, or of the blue cube?
        parse("put the red cube next to the blue cube on the left side")


@pytest.mark.parametrize("text,expected", [
    ("Make a pile of four pink cubes.", ["pile(pink,pink,pink,pink)"]),
    ("Make a pile of four cubes: two green, one purple, one red.", ["pile(green,green,purple,red)"]),
    ("make a single heap of 3 green cubes in the back left corner", ["pile(green,green,green)@back_left"]),
])
def test_one_pile_of_the_cubes_named(text, expected):
    assert meaning(parse(text)) == expected


def test_one_pile_of_cubes_nobody_named_is_refused():
    with pytest.raises(BadInput, match="does not say which cubes"):
        parse("make a pile of the cubes")


def test_one_pile_compiles_and_its_goal_holds(tmp_path):
    from rpg.compiler import compile_instruction

    result = compile_instruction("make one pile of the red, green and blue cubes", tmp_path, name="pile")
    assert result.valid, result.gates


@pytest.mark.parametrize("text,expected", [
    # stranger13: a counted group and one more cube on top or below; an end said of a named cube; one tower
    ("Build a stack of two blue cubes and put the green cube on top.", ["stack(blue,blue,green)"]),
    ("Build a tower of five cubes with a red cube at the bottom and four yellow cubes above it.",
     ["stack(red,yellow,yellow,yellow,yellow)"]),
    ("Stack a gray cube, a black cube and a white cube with gray on top and white at the bottom.", ["stack(white,black,gray)"]),
    ("Make one tower with the cubes red, white and blue, the red in the base and the blue in the top.", ["stack(red,white,blue)"]),
])
def test_a_counted_group_with_one_more_on_top_and_ends_of_named_cubes(text, expected):
    assert meaning(parse(text)) == expected


def test_a_counted_group_and_one_more_must_add_up():
    with pytest.raises(BadInput):  # six said, five described
        parse("Build a tower of six cubes with a red cube at the bottom and four yellow cubes above it.")


@pytest.mark.parametrize("text,expected", [
    ("Place a red cube on each side of the black cube.", ["between(black;red,red)"]),
    ("place the yellow cube in the center of the table and the two orange cubes on either side of it",
     ["between(yellow;orange,orange)", "in_region(yellow,center)"]),
])
def test_cubes_on_each_side_put_one_between_them(text, expected):
    assert meaning(parse(text)) == expected


def test_leave_says_where_a_cube_ends_and_stays_an_action_otherwise():
    assert meaning(parse("leave the white cube on the red patch")) == ["on_patch(white,patch:red)"]
    with pytest.raises(BadInput, match="action"):
        parse("leave the room")


@pytest.mark.parametrize("text,expected", [
    # a wall's layers said as a count: it had been a wall of two layers whatever the count ("3 layers, 2 cubes per layer"
    # had compiled four cubes), and "4 cyan cubes per row" had made a wall of four
    ("Build a wall with 3 layers, 2 cubes per layer", ["wall(red,red,red,red,red,red)"]),
    ("Build a wall of 3 layers, 2 cubes each", ["wall(red,red,red,red,red,red)"]),
    ("Build a wall of 2 rows, 4 cyan cubes per row.", ["wall(cyan,cyan,cyan,cyan,cyan,cyan,cyan,cyan)"]),
    ("Build a wall with three red cubes in the bottom row and three blue cubes in the row above",
     ["wall(red,red,red|blue,blue,blue)"]),
    ("Build a wall two cubes high: three grey cubes in the bottom row and three brown cubes on top of them.",
     ["wall(gray,gray,gray|brown,brown,brown)"]),
    ("Build a pyramid of six green cubes: three on the bottom, two in the middle and one on top",
     ["pyramid(green,green,green,green,green,green)"]),  # the middle layer, not the table's centre
])
def test_a_walls_layers_counted_and_rows_said_one_above_another(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a tower's levels and a grid's rows and columns said as counts (the levels had been dropped: a tower of two)
    ("build a tower with 4 levels", ["stack(red,blue,green,yellow)"]),
    ("build a red tower with four levels", ["stack(red,red,red,red)"]),
    ("a grid of 2 rows, 3 cubes each", ["grid(2x3:red,red,red,red,red,red)"]),
    ("make a grid with 2 columns and 3 rows of blue cubes", ["grid(3x2:blue,blue,blue,blue,blue,blue)"]),
])
def test_levels_rows_and_columns_said_as_counts(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,why", [
    # stranger14's silent errors
    ("which of the cubes is closest to the green patch", "question"),  # a question without its mark had compiled
    ("Part (c): the same pyramid as in part (b), but built from blue cubes.", "same pyramid as in"),  # an earlier part
    ("The white cube, the black cube on top of, please place.", "could not find"),  # which is on which? (two readers differ)
    ("Red cube, blue cube on top of, put please.", "could not find"),  # another stranger read this one the other way
    ("Make a row from two cubes gray and the cube brown, and the cube brown is in middle of them.", "could not find"),
])
def test_a_bare_question_an_earlier_part_and_a_stranded_of_are_refused(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


def test_a_towers_ends_and_its_counted_middle_said_as_clauses():  # the middle's count had reached one cube
    assert meaning(parse("stack four cubes; the bottom one is blue, the top one is red and the two in between are green")) \
        == ["stack(blue,green,green,red)"]


def test_piles_match_in_any_listed_order():
    from rpg.schema.meaning import matches

    assert matches("piles(red,red,blue,blue;by=color)", ["piles(blue,blue,red,red;by=color)"])
    assert matches("pile(red,blue)@center", ["pile(blue,red)@center"])
    assert not matches("piles(red,red,blue;by=color)", ["piles(blue,blue,red;by=color)"])


@pytest.mark.parametrize("text,expected", [
    # stranger14's voices: an assistant's reply, a user story, an exam question, a table row, hashtags, a row's roles
    ("Sure! Here is the task: place the purple cube on top of the orange cube. Let me know if you need anything else!",
     ["stack(orange,purple)"]),
    ("As a lab manager, I want the robot to stack the blue cube on the yellow cube, so that the bench looks tidy.",
     ["stack(yellow,blue)"]),
    ("Problem 2. The robot must finish with the red cube on top of the blue cube and the yellow cube on top of the red "
     "cube. (5 points)", ["stack(blue,red,yellow)"]),
    ("task_07 | stack | red on blue", ["stack(blue,red)"]),
    ("today's demo: spell CAT with the letter blocks #HRI #demo",
     ["line[left_to_right](C,A,T)", "reads(C,A,T;direction=left_to_right,face=up,text=CAT)"]),
    ("Row of four cubes: the leftmost is red, the rightmost is blue, and the two in between are yellow.",
     ["line[left_to_right](red,yellow,yellow,blue)"]),
    ("a row of five: a red cube at each end and three white cubes between them",
     ["line[left_to_right](red,white,white,white,red)"]),
    ("stack the blue cube onto the red cube, not the other way round", ["stack(red,blue)"]),
    ("the blue patch should have the red cube on it", ["on_patch(red,patch:blue)"]),
])
def test_replies_stories_exams_table_rows_and_a_rows_roles(text, expected):
    assert meaning(parse(text)) == expected


def test_either_one_on_top_leaves_the_order_free():
    schema = parse("Make a stack out of the red cube and the blue cube, either one on top.")
    assert meaning(schema) == ["stack(red,blue)"] and "any order" in schema.goal_summary


def test_a_rotation_by_degrees_is_refused_as_an_action():  # it had been refused as an unknown quantity word
    with pytest.raises(Inexpressible, match="rotation"):
        parse("Rotate the blue cube 90 degrees and leave it on top of the red cube.")



def test_runs_of_blanks_are_read_as_one():  # thousands of spaces had taken minutes (patterns with optional blanks)
    schema = parse("put the red cube" + " " * 7800 + "on the blue cube")
    assert meaning(schema) == ["stack(blue,red)"] and schema.instruction.count(" ") > 7800  # kept as written


@pytest.mark.parametrize("text,expected", [
    # stranger16: a sort said by its largest or smallest label at one end (the listed order had been kept: silent)
    ("Make a tower, biggest number at the bottom: cubes 1, 2 and 3.", ["stack(3,2,1)"]),
    ("Stack 1, 2 and 3, the highest number at the base.", ["stack(3,2,1)"]),
    ("Put digits 4, 2 and 7 in a row, largest on the left.", ["line[left_to_right](7,4,2)"]),
    ("Put the digit cubes 4, 2 and 7 in a row, smallest on the right.", ["line[left_to_right](7,4,2)"]),
    ("Put the digit cubes 4, 7 and 2 in a row, highest number on the right.", ["line[left_to_right](2,4,7)"]),
    ("Line up the digits 3, 1, 2 with the smallest in front.", ["line[front_to_back](1,2,3)"]),
])
def test_a_sort_said_by_the_label_at_one_end(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # stranger16's voices: a rulebook, an acceptance criterion, a handout's labels, a spec's section number, a chat's
    # emoji shortcodes and announcement, a voice assistant, an annotator's caption of what the arm did, a Spanish habit
    ("Rule 5.2: A team scores when its red cube rests on the green goal patch.", ["on_patch(red,patch:green)"]),
    ("Acceptance criterion: given the cubes, when the task finishes, then the blue cube is left of the orange cube.",
     ["left_of(blue,orange)"]),
    ("Lab 4, part A: place the pink cube between the two gray cubes.", ["between(pink;gray,gray)"]),
    ("By the end of the exercise the white cube should be sitting on the yellow patch.", ["on_patch(white,patch:yellow)"]),
    ("5.3 The final structure shall be a row of three red cubes.", ["line(red,red,red)"]),
    ("hey can the bot stack blue on red :pray: thx", ["stack(red,blue)"]),
    ("ok new eval task :point_down: row of 3 orange cubes, that's it :white_check_mark:", ["line(orange,orange,orange)"]),
    ("put the red cube :red_circle: on the blue patch when you get a sec", ["on_patch(red,patch:blue)"]),
    ("Alexa, tell the robot to make a tower of three yellow blocks.", ["stack(yellow,yellow,yellow)"]),
    ("The arm moved the green block to the left of the blue block.", ["left_of(green,blue)"]),
    ("the gripper stacked the pink cube onto the white cube and then stopped", ["stack(white,pink)"]),
    ("Is necessary to make a line with the three cubes pink.", ["line(pink,pink,pink)"]),
    # words: a target field is a patch, a zone a region, "well away" far, "just leave" a place to end in
    ("Put the orange cube onto the green target field.", ["on_patch(orange,patch:green)"]),
    ("Place the red cube in the left zone.", ["in_region(red,left)"]),
    ("Keep the green block well away from the yellow block.", ["far_from(green,yellow)"]),
    ("Just leave the orange cube somewhere on the right side of the table.", ["in_region(orange,right)"]),
])
def test_rulebooks_criteria_chats_captions_and_voice_requests(text, expected):
    assert meaning(parse(text)) == expected


def test_labels_listed_with_spaces_are_the_labels_sorted():  # "A B C" had been read as 4 letters (a D invented)
    assert meaning(parse("line up A B C in alphabetical order left to right")) == ["line[left_to_right](A,B,C)"]


@pytest.mark.parametrize("text", ["When the green patch is empty, put the yellow cube on it.",
                                  "If the red cube is on the left, put it on the blue cube.",
                                  "Move the arm back to its home position."])
def test_conditions_and_arm_motions_stay_refused(text):  # the new frames take only a score, a run's end, a caption
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a cube placed in a region, then another related to it: "it" is the one cube of the clause before
    ("Put the red cube in the center and the blue cube to its left.", ["in_region(red,center)", "left_of(blue,red)"]),
    ("Put the blue cube on the right side and the green one beside it.", ["in_region(blue,right)", "next_to(blue,green)"]),
    ("Put the red cube in the back and the green cube in front of it.", ["in_front_of(green,red)", "in_region(red,back)"]),
    ("Put the red cube on the left and the blue cube on the right.", ["left_of(red,blue)"]),  # still one relation's sides
])
def test_a_cube_placed_in_a_region_then_another_related_to_it(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # counted cubes that had reached one cube: "the two red cubes" under a named top, one cube on each of N,
    # a counted colour after its noun agreeing in number, a label cube named without its article
    ("Stack the two red cubes and put the white cube on top.", ["stack(red,red,white)"]),
    ("Put one yellow cube on each of the two blue cubes.", ["stack(blue,yellow)", "stack(blue,yellow)"]),
    ("Put the two cubes oranges in the center of the table.", ["in_region(orange,center)", "in_region(orange,center)"]),
    ("so the the tower should be uh three cubes purple purple and then uh orange at the top",
     ["stack(purple,purple,orange)"]),  # a list after the noun stays a list
    ("Put digit 7 on top of digit 2.", ["stack(2,7)"]),
    ("Place digit 3 between digit 1 and digit 5.", ["between(3;1,5)"]),
])
def test_counted_cubes_each_of_and_bare_label_nouns(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # piles: one pile of a count of unnamed cubes, of "the orange cubes", on a goal patch; "pile four cubes" is one pile
    ("Make a pile of four cubes in the front right.", ["pile(blue,green,red,yellow)@front_right"]),
    ("Pile four cubes.", ["pile(blue,green,red,yellow)"]),  # had been three piles of six cubes: silently wrong
    ("Make a pile of the orange cubes in the center of the table.", ["pile(orange,orange,orange)@center"]),
    ("Make a heap of the three red cubes on the yellow patch.", ["on_patch(red,red,red,patch:yellow)", "pile(red,red,red)"]),
    ("push the pile of red blocks into the blue patch", ["on_patch(red,red,patch:blue)"]),
    # a tower's counted colours at its ends; a line's end "closest to the front"; "leftmost should be ..., then ..."
    ("Build a tower of four: two green at the bottom and two pink on top.", ["stack(green,green,pink,pink)"]),
    ("Make a line of red, white and blue from front to back, red closest to the front.",
     ["line[front_to_back](red,white,blue)"]),
    ("Leftmost should be the red cube, then blue, then yellow, all in one neat row.",
     ["line[left_to_right](red,blue,yellow)"]),
    ("The white cube shall stand left beside the gray cube.", ["left_of(white,gray)"]),
    ("Set the white cube right next to the grey one.", ["next_to(gray,white)"]),  # "right" there is only emphasis
])
def test_piles_counted_ends_and_a_lines_first_cube(text, expected):
    assert meaning(parse(text)) == expected


def test_a_structure_too_wide_for_its_patch_is_refused():
    with pytest.raises(ParseError, match="do not fit on one goal patch"):
        parse("Make a row of three red cubes on the yellow patch.")


def test_a_line_end_that_contradicts_its_direction_is_refused():
    with pytest.raises(ParseError):
        parse("Make a line of red, white and blue from front to back, blue closest to the front.")


@pytest.mark.parametrize("text,expected", [
    # a start said by "there's a tower of ... with X at the bottom", by "unstack the X-on-Y tower", and every cube sent
    # to the table ("both cubes sit on the table")
    ("There's a tower of blue, green and red with blue at the bottom. Take the red one off and set it on the table.",
     ["on_table(red)", "start:stack(blue,green,red)"]),
    ("There is a tower of blue, green and red with red at the bottom. Put the blue cube next to the green cube.",
     ["next_to(blue,green)", "start:stack(red,green,blue)"]),
    ("Unstack the yellow-on-white tower so both cubes sit on the table.", ["on_table(white)", "on_table(yellow)", "start:stack(white,yellow)"]),
    ("Unstack the tower of green on yellow and set both cubes on the table.", ["on_table(green)", "on_table(yellow)", "start:stack(yellow,green)"]),
    ("Initially red is on blue and green is on red. Put all the cubes on the table.",
     ["on_table(blue)", "on_table(green)", "on_table(red)", "start:stack(blue,red,green)"]),
])
def test_starts_said_by_a_tower_or_by_unstack(text, expected):
    assert meaning(parse(text)) == expected


def test_a_goal_after_a_start_is_never_read_with_the_start_as_the_goal():
    # the start's "yellow is on white" had become the goal when the goal's words were not read: silently wrong
    with pytest.raises(BadInput):
        parse("Initially the yellow cube is on the white cube. Put every other cube somewhere.")
    with pytest.raises(BadInput):  # a tower's end that is neither end of its list is no start rpg builds
        parse("There is a tower of blue, green and red with green at the bottom. Put the blue cube on the table.")


@pytest.mark.parametrize("text,why", [
    ("Line up the gold, silver and red cubes from left to right.", "colour the palette does not have"),
    ("Place the white cube anywhere but the left side.", "negation"),
    ("Hey robot, what does a pyramid look like?", "question"),
    ("Put the white cube on the red patch and on the blue patch at the same time.", "contradicts"),
])
def test_must_refuse_texts_are_refused_for_their_reason(text, why):
    with pytest.raises(BadInput, match=why):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # label cubes given their places in a tower (the bare labels had been dropped and the tower built of coloured cubes)
    ("Build a two-cube tower: 9 at the bottom, 0 on top.", ["stack(9,0)"]),
    ("Stack the digits so that 1 is at the bottom and 3 is on top, with 2 in between.", ["stack(1,2,3)"]),
    # said in turn from the base (had been refused: the labels were lost and two coloured cubes built)
    ("Build a tower of number blocks: 7 at the bottom, then 2, then 9.", ["stack(7,2,9)"]),
    ("Build a tower of number blocks: 1 at the bottom, then 2, then 3.", ["stack(1,2,3)"]),  # (a fourth digit had been added)
    ("Build a tower of letter cubes: A at the bottom, then B, then C.", ["stack(A,B,C)"]),
    ("Stack the number cubes with 1 at the bottom, 2 in the middle and 3 on top.", ["stack(1,2,3)"]),
    ("Stack the letters with A on top and C at the bottom, B in the middle.", ["stack(C,B,A)"]),  # had been @center
    ("Stack the digit cubes 1, 2, 3 and 4 into one tower, 4 at the bottom and 1 on top.", ["stack(4,3,2,1)"]),
    ("Build a tower of five cubes: 2 red at the bottom and 3 blue on top.", ["stack(red,red,blue,blue,blue)"]),
    ("Build a tower of letter cubes with A at the bottom, then B, then C on top", ["stack(A,B,C)"]),  # B had been dropped
])
def test_label_cubes_given_their_places_in_a_tower(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # stranger17's silent errors: a second relation after "but" is the subject's; "one pile per colour" is several piles
    ("Put the red cube next to the blue cube but far from the green cube.", ["far_from(green,red)", "next_to(blue,red)"]),
    ("Sort the two red, two green and two blue cubes into one pile per colour.",
     ["piles(blue,blue,green,green,red,red;by=color)"]),
    # a list that restates the bottom cube it follows (it had been counted twice: a seventh cube)
    ("Stack the cubes in rainbow order, red at the bottom: red, orange, yellow, green, blue, purple.",
     ["stack(red,orange,yellow,green,blue,purple)"]),
    ("Build a tower with red at the bottom: red, blue, green.", ["stack(red,blue,green)"]),
])
def test_a_relation_after_but_and_one_pile_per_colour(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", ["Build a tower: 9 at the bottom, 0 at the bottom.",
                                  "Build a tower: " + ", ".join(f"{i % 10} at the bottom" for i in range(150))])
def test_digits_given_tower_places_that_make_no_order_are_refused(text):  # they had built a tower of two coloured cubes
    with pytest.raises(ParseError):
        parse(text)


def test_a_run_of_emoji_shortcodes_is_read_as_one_blank():  # 270 of them had taken 50 s (runs of blanks, quadratic)
    assert meaning(parse("put red on blue " + ":a_b: " * 270)) == ["stack(blue,red)"]


@pytest.mark.parametrize("text,expected", [
    # stranger18's silent errors: a sort's end said by a comparative, of two labels; a label range; roles of listed labels
    ("Stack digit cubes 5 and 2 with the larger number on top.", ["stack(2,5)"]),
    ("Stack digit cubes 5 and 2 with the larger number at the bottom.", ["stack(5,2)"]),
    ("Stack the digits 1 through 3 with the highest digit at the bottom.", ["stack(3,2,1)"]),
    ("Stack the digits 1 through 3 with the biggest at the very bottom.", ["stack(3,2,1)"]),
    ("Arrange the digits 1 to 4 in a row, smallest on the left.", ["line[left_to_right](1,2,3,4)"]),
    ("Stack letters T, O, P so that T is on top and P is at the bottom.", ["stack(P,O,T)"]),
    # each list of a layered wall is a layer (the places had been dropped: the colours in any layer)
    ("Wall of two layers: red, red, red below, yellow, yellow, yellow above.", ["wall(red,red,red|yellow,yellow,yellow)"]),
])
def test_stranger18_sorts_ranges_roles_and_layers(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,summary", [
    # cubes nobody named, made up to reach a said count, stand anywhere; the named ones where they were said to be
    ("Build a tower of four cubes with the two green ones at the bottom.",
     "a stack of green_1, green_2, red, blue in any order; green_1 at the bottom; green_2 second from the bottom"),
    ("Build a tower of three blocks with a yellow block on top.", "a stack of red, blue, yellow with yellow on top, the rest in any order"),
    # a role that moves a listed label away from the list's place: the list names the cubes, not their order
    ("Stack letters T, O, P so that O is on top.",
     "a tower of letter_t, letter_p, letter_o in any order, with letter_o third from the bottom"),
])
def test_a_tower_fixes_only_the_places_its_words_give(text, summary):
    assert parse(text).goal_summary == summary


@pytest.mark.parametrize("text", [
    "Stack the yellow cube on the pink cube, with the pink cube on top.",
    "Stack the yellow cube on the pink cube, with the yellow cube at the bottom.",
    "Put red on blue so that blue is on top",
])
def test_a_tower_end_that_contradicts_the_relation_is_refused(text):  # the end had been dropped: compiled
    with pytest.raises(ParseError, match="contradicts"):
        parse(text)


def test_a_tower_end_that_agrees_with_the_relation_is_read():
    assert meaning(parse("Stack the yellow cube on the pink cube, with the yellow cube on top.")) == ["stack(pink,yellow)"]


@pytest.mark.parametrize("expected,actual,ok", [
    ("next_to(pink,Z)", ["next_to(Z,pink)"], True),  # symmetric: either order
    ("next_to(yellow,?)", ["next_to(yellow,zz)"], True),
    ("next_to(?,yellow)", ["next_to(yellow,zz)"], True),
    ("far_from(b,a)", ["far_from(a,b)"], True),
    ("next_to(red,?)", ["next_to(a,c)"], False),
    ("left_of(b,a)", ["left_of(a,b)"], False),  # not symmetric
])
def test_a_symmetric_relation_matches_in_either_order(expected, actual, ok):
    assert matches(expected, actual) is ok


@pytest.mark.parametrize("text,expected", [
    # stranger18's refusals: labelled headings and a task's quoted name, a reviewer's sign-off, a row's two ends and middle
    ('Proposal (#212): new eval task "letters in order", cubes A, B, C, D arranged left to right alphabetically.',
     ["line[left_to_right](A,B,C,D)"]),
    ("Episode goal (from the dataset card): three pink cubes placed on the orange patch.", ["on_patch(pink,pink,pink,patch:orange)"]),
    ("Task T3 (Year 2 milestone): three-block tower, order blue-yellow-red from base to top.", ["stack(blue,yellow,red)"]),
    ("Acceptance criteria: the blue cube ends next to the purple cube. Ship it.", ["next_to(blue,purple)"]),
    ("A row of three cubes, red in the middle, green on both ends.", ["line[left_to_right](green,red,green)"]),
    # these two had compiled silently wrong: a made-up blue cube in a row of any order
    ("A row of three cubes with green on both ends and red in the middle.", ["line[left_to_right](green,red,green)"]),
    ("A row of three: green at each end and red in the middle.", ["line[left_to_right](green,red,green)"]),
    # a count said of one colour is that colour's, not the tower's
    ("Stack both white cubes and the gray cube into one tower with gray on top.", ["stack(white,white,gray)"]),
    ("Stack 3 yellow cubes and put the 4 cube on top.", ["stack(yellow,yellow,yellow,4)"]),
])
def test_stranger18_headings_ends_and_counted_colours(text, expected):
    assert meaning(parse(text)) == expected


def test_a_tower_counted_as_a_whole_keeps_its_count():  # "a two-cube tower" is the tower's count, not pink's
    with pytest.raises(ParseError):
        parse("Make a two-cube tower of pink and cyan with the pink cube both on top and at the bottom.")


@pytest.mark.parametrize("text,expected", [
    # stranger18's refusals: a region of the table said with "region", a plural colour noun, "too" after a clause,
    # "between them" of a label, "in bottom", a trailing "between", cubes labelled two labels at once
    ("Slide the orange cube into the left region.", ["in_region(orange,left)"]),
    ("Put the red cube in the front left region.", ["in_region(red,front_left)"]),
    ("A tower of 3 reds.", ["stack(red,red,red)"]),
    ("Goal state: blue cube on the red patch, green cube on the red patch too.", ["on_patch(blue,green,patch:red)"]),
    ("Stack the digit cubes so that 1 is at the bottom and 3 is at the top, with 2 between them.", ["stack(1,2,3)"]),
    ("Make a tower with the cubes green, orange and purple, the green in bottom.", ["stack(green,orange,purple)"]),
    ("Stack the cubes so the pink one is at the very top and the white one at the very bottom, with gray between.",
     ["stack(white,gray,pink)"]),
    ("Put the cube labelled 5 between the cubes labelled 4 and 6.", ["between(5;4,6)"]),
])
def test_stranger18_regions_plurals_and_roles(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # colours left free for cubes nobody names by colour (had been refused as a contradiction with the named cube)
    ("Put two cubes on top of the purple cube, any colours.", "a stack of purple, red, blue with purple at the bottom, the rest in any order"),
    ("Stack three cubes with yellow at the bottom; the other two can be anything.",
     "a stack of yellow, red, blue with yellow at the bottom, the rest in any order"),
    # "two cubes on top of the purple cube" had compiled one red cube on it (silently wrong)
    ("Put two cubes on top of the purple cube.", "a stack of purple, red, blue with purple at the bottom, the rest in any order"),
])
def test_cubes_nobody_names_stand_anywhere_in_any_colour(text, expected):
    assert parse(text).goal_summary == expected


def test_colours_left_free_of_cubes_all_named_by_colour_are_refused():
    with pytest.raises(Inexpressible, match="leaves the colours free"):
        parse("Put the red cube left of the blue cube. Colours don't matter.")


@pytest.mark.parametrize("text,expected", [
    # the names of what is being written are no part of the goal
    ("far task: the red cube should be far from the green cube.", ["far_from(green,red)"]),
    ("Hi! For this experiment the robot should place the brown block on top of the white block.", ["stack(white,brown)"]),
    ("Hey - quick one: the eval I need is just the brown cube moved to the front of the table.", ["in_region(brown,front)"]),
])
def test_what_the_writer_calls_the_task_is_ignored(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # stranger19's silent errors: the goal's "both cubes" are the start's (a blue cube had been made up); a start said as
    # what the robot starts with (it had become part of the goal); "two cubes of any colour go on top of" (one cube)
    ("Initial state: yellow on red. Goal: both cubes on the table, side by side.", ["next_to(red,yellow)", "start:stack(red,yellow)"]),
    ("Initially yellow is on white. Put the cubes side by side.", ["next_to(white,yellow)", "start:stack(white,yellow)"]),
    ("The robot starts with the white cube on the black cube and has to move the white cube onto the pink patch.",
     ["on_patch(white,patch:pink)", "start:stack(black,white)"]),
])
def test_stranger19_starts_and_their_cubes(text, expected):
    assert meaning(parse(text)) == expected


def test_counted_cubes_of_any_colour_on_a_cube_are_a_tower_on_it():
    assert parse("Two cubes of any colour go on top of the black cube.").goal_summary == \
        "a stack of black, red, blue with black at the bottom, the rest in any order"


@pytest.mark.parametrize("text,expected", [
    # stranger23's refusals and its silent error, by class (seventeenth session)
    ("The initial tower is red, blue, green from the bottom up. The goal is to move the green cube onto the red patch.",
     ["on_patch(green,patch:red)", "start:stack(red,blue,green)"]),  # the start had been read as the goal, green lost
    ("push the pink block to the top of the table", ["in_region(pink,back)"]),  # a map's top is the far side
    ("push the green block to the bottom of the table", ["in_region(green,front)"]),
    ("move the red block to the bottom", ["in_region(red,front)"]),  # no tower to have a bottom
    ("Success criterion for this episode, checked by the scripted evaluator after the arm returns home: the cyan cube "
     "is in the back right corner.", ["in_region(cyan,back_right)"]),  # a long label that names nothing of the task
    ("For this rollout we only check one relation: the orange cube right of the purple cube.", ["right_of(orange,purple)"]),
    ("The gray cube should be far from the black cube at the end of the episode.", ["far_from(black,gray)"]),
    ("Put one cube on the red patch and another on the blue patch; which cubes does not matter.",
     ["on_patch(blue,patch:blue)", "on_patch(red,patch:red)"]),
    ("stack number four on number two, and number two on number seven.", ["stack(7,2,4)"]),  # two coloured cubes before
    ("line up the digits one, two and three", ["line(1,2,3)"]),  # a line of four before
    ("Put the cyan cube left of the pink cube and the pink cube left of the white cube, all three in the front half of "
     "the table.", ["in_region(cyan,front)", "in_region(pink,front)", "in_region(white,front)", "left_of(cyan,pink)",
                    "left_of(pink,white)"]),  # the cyan cube had been left out of the region
])
def test_stranger23_classes_read_as_said(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    # a cube that stands in the tower said, put on a patch by a verb of its own: the tower's base had gone there instead
    ("Build a tower of red, blue, green from the bottom up. Move the green cube onto the red patch.", "stands on another cube"),
    ("Stack red on blue, then put the red cube on the green patch", "stands on another cube"),
    ("Put the cyan cube left of the pink cube and the pink cube left of the white cube, all 4 in the front half of the table.", "counts 4 cubes"),
])
def test_a_place_that_cannot_be_the_cube_s_is_refused(text, words):
    with pytest.raises(ParseError, match=words):
        parse(text)


def test_a_tower_on_a_patch_and_its_base_on_a_patch_still_compile():
    assert meaning(parse("Build a tower of red, blue, green on the red patch")) == ["on_patch(red,patch:red)", "stack(red,blue,green)"]
    assert meaning(parse("Stack the red block on the blue block and put the blue block on the green patch")) == [
        "on_patch(blue,patch:green)", "stack(blue,red)"]


@pytest.mark.parametrize("text,expected", [
    # stranger23's refusal classes, second pass
    ("Build a tower of three cubes on the purple patch.",  # the patch's colour had counted as a named cube's
     ["on_patch(red,patch:purple)", "stack(red,blue,green)"]),
    ("Initial: pink cube on top of brown cube. Target: both cubes resting on the table.", ["on_table(brown)", "on_table(pink)", "start:stack(brown,pink)"]),
    ("Initial: blue cube with the white cube on top of it. Target: the white cube on the yellow patch.",
     ["on_patch(white,patch:yellow)", "start:stack(blue,white)"]),
    ("Start: black on white on gray, gray at the bottom. Take the black cube off and set it on the table.",
     ["on_table(black)", "start:stack(gray,white,black)"]),
    ("Unstack: the start is a tower of four cubes, white at the bottom, then gray, black, brown. Put the brown one on the table.",
     ["on_table(brown)", "start:stack(white,gray,black,brown)"]),
    ("Unstack the tower (bottom to top: green, yellow, red) so that every cube ends up on the table.",
     ["on_table(green)", "on_table(red)", "on_table(yellow)", "start:stack(green,yellow,red)"]),
    ("Stack 2 on 1 and 4 on 3.", ["stack(1,2)", "stack(3,4)"]),
    ("Stack the red cube on the green cube. Separately, put the white cube in the back.", ["in_region(white,back)", "stack(green,red)"]),
    ("Stack pink on brown, put the cyan cube on the white patch, and move the gray cube to the front.",
     ["in_region(gray,front)", "on_patch(cyan,patch:white)", "stack(brown,pink)"]),
    ("In the final row the leftmost cube should be black, the rightmost brown, and the middle one yellow.",
     ["line[left_to_right](black,yellow,brown)"]),
    ("Repro for #142: put the yellow cube behind the gray cube, run 20 seeds.", ["behind(yellow,gray)"]),
])
def test_stranger23_second_pass(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "Start: black on white on gray, black at the bottom. Take the black cube off and set it on the table.",  # not its bottom
    "Unstack: the start is a tower of three cubes, white at the bottom, then gray, black, brown. Put the brown one on the table.",
])
def test_a_start_said_twice_must_agree(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a cube said to stay, be left or be kept somewhere ends there; "Look, ..." and "to complete this task," frame it
    ("Stack the brown cube on the black cube and leave the pair in the back left corner.", ["stack(black,brown)@back_left"]),
    ("The cube yellow must stay at the left of the cube orange.", ["left_of(yellow,orange)"]),
    ("The cube orange must stay on the patch purple.", ["on_patch(orange,patch:purple)"]),
    ("Look, a pink patch! Put the pink block on the pink patch, honey.", ["on_patch(pink,patch:pink)"]),
    ("To complete this task, the robot should put the red cube on the blue cube.", ["stack(blue,red)"]),
])
def test_stay_leave_keep_and_framing(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    ("The scene starts with blue stacked on red. Unstack it so both cubes sit on the table.", ["on_table(blue)", "on_table(red)", "start:stack(red,blue)"]),
    ("The final scene should have the orange cube resting on top of the purple cube.", ["stack(purple,orange)"]),
    ("The end state you are looking for is a circle made of five cubes: two red, two yellow and one blue.",
     ["circle(blue,red,red,yellow,yellow)"]),
    ("Put the red cube on the blue cube. That's the whole task.", ["stack(blue,red)"]),
])
def test_goal_framings_and_closings(text, expected):
    assert meaning(parse(text)) == expected


def test_either_order_leaves_the_tower_in_any_order():
    assert parse("A tower of two cubes, red and blue, in either order.").goal_summary == "a stack of red, blue in any order"


@pytest.mark.parametrize("text,expected", [
    # a colour listed twice in a tower on a patch is two cubes (the tower had lost one, silently)
    ("Stack red, red, blue on the green patch", ["on_patch(red,patch:green)", "stack(red,red,blue)"]),
    ("Build a tower from bottom to top: pink, pink, pink, red on the orange goal patch", ["on_patch(pink,patch:orange)", "stack(pink,pink,pink,red)"]),
])
def test_a_colour_listed_twice_is_two_cubes(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "To do: tower of red and white, white on top; brown cube in the front right corner.",  # white's role, not a third cube
    "Pile the two cyan blocks and the pink block on top of each other.",  # no order said (it had been read bottom to top)
])
def test_a_role_or_each_other_adds_no_cube_and_no_order(text):
    try:
        got = meaning(parse(text))
    except BadInput:
        return
    assert "stack(red,white,white)" not in got and "stack(cyan,cyan,pink)" not in got


@pytest.mark.parametrize("text,expected", [
    # a hostile tester's silent errors (seventeenth session), now read as said
    ("Put the green cube on the wite cube.", ["stack(white,green)"]),  # a typo in a colour's slot is a colour ("write" before)
    ("Put the cian cube left of the blue cube.", ["left_of(cyan,blue)"]),  # ("can": the cube had become red)
    ("Stack wite, blue, green from bottom to top.", ["stack(white,blue,green)"]),  # (the white cube had gone)
    ("Build a tower: the top is red, then blue, then green.", ["stack(green,blue,red)"]),  # listed from the top
    ("Make a tower of red, blue, green where blue is highest", ["stack(red,green,blue)"]),  # (a fourth cube, blue, before)
    ("Make a row of red, blue and green, red first, from left to right", ["line[left_to_right](red,blue,green)"]),
    ("Line up red, green and blue in that order.", ["line[sequence](red,green,blue)"]),  # the order had been dropped
    ("Make a pile of red and blue and a pile of green.", ["pile(blue,red)", "pile(green)"]),  # two piles (one before)
])
def test_attack_silent_errors_read_as_said(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    ("Put the pick cube on the white cube.", "'pick' stands where a cube's colour"),
    ("Put red on blue, or on green.", "'or' offers alternatives"),
    ("Stack red on blue or green on yellow.", "'or' offers alternatives"),  # (both stacks before)
    ("Put the red cube, which is currently on blue, on the table.", "which is currently on"),  # (red on blue before)
    ("Red is on blue. Reverse the tower.", "turns around"),
    ("Build a tower of red, blue, green, yellow with red second from the top.", "rank from an end"),  # (a 5th cube)
    ("Make a row of red, blue and green, blue first, from left to right", "does not start with"),
    ("Stack the red cube on top of the tower.", "tower the instruction has not described"),  # (3 cubes made up)
    ("Stack two cubes of the same colour.", "share a colour"),
    ("Put the blue green cube on the white cube.", "one cube by two colours"),
    ("Put red, green, blue in a circle in that order.", "orders the cubes of a circle"),
    ("Put red, blue, green, yellow into two piles.", "say which cubes go in each pile"),  # (12 cubes before)
])
def test_attack_silent_errors_refused(text, words):
    with pytest.raises(BadInput, match=re.escape(words)):
        parse(text)


@pytest.mark.parametrize("text", [
    # a relation said between two named cubes must be in the goal: "on the blue cube" had been dropped into a row of four
    "Make a row of red, blue and green and put the yellow cube on the blue cube.",
    "Make a row of red, blue, green. Put the yellow cube on the blue cube.",
])
def test_a_relation_between_two_named_cubes_is_never_dropped(text):
    with pytest.raises(ParseError, match="relates two cubes that task does not relate"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Put the digits 7, 3, 5 in a row in reverse order left to right.", ["line[left_to_right](5,3,7)"]),  # ("reverse" dropped)
    ("Line up red, green and blue in reverse order from left to right.", ["line[left_to_right](blue,green,red)"]),
    ("Stack red on blue and put the yellow cube next to the green cube.", ["next_to(green,yellow)", "stack(blue,red)"]),
])
def test_reverse_order_and_kept_relations(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a second hostile tester's silent errors: lists from the top, roles said by colon
    ("Stack red, green, blue from the top down.", ["stack(blue,green,red)"]),
    ("Tower (top first): red, green, blue.", ["stack(blue,green,red)"]),
    ("Stack A, B, C, top down.", ["stack(C,B,A)"]),
    ("Make a tower. Top: red. Middle: green. Bottom: blue.", ["stack(blue,green,red)"]),  # (red at the bottom before)
    ("Three-cube tower. Base: grey. Middle: pink. Top: cyan.", ["stack(gray,pink,cyan)"]),
])
def test_lists_from_the_top_and_colon_roles(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    ("Build a tower with green between red and blue.", "stacked on each other"),  # (red on blue, green beside: before)
])
def test_between_or_middle_of_a_tower_said_loosely_is_refused(text, words):
    with pytest.raises(ParseError, match=re.escape(words)):
        parse(text)


@pytest.mark.parametrize("text,summary", [
    # an end given in a sentence of its own leaves the rest of a listed stack free (a full order had been demanded)
    ("Stack red, green, blue; red must be on top.", "a stack of green, blue, red with red on top, the rest in any order"),
    ("Stack red, green, blue. Blue must be at the bottom.", "a stack of blue, red, green with blue at the bottom, the rest in any order"),
])
def test_an_end_said_apart_leaves_the_rest_free(text, summary):
    assert parse(text).goal_summary == summary


def test_each_other_after_several_cubes_is_refused():
    """"red on blue and green on yellow, side by side" had made up a second yellow cube beside the first."""
    with pytest.raises(ParseError, match="each other' after several cubes"):
        parse("Place red on blue and green on yellow, side by side.")
    assert meaning(parse("put two red cubes next to each other")) == ["next_to(red,red)"]


@pytest.mark.parametrize("text,expected", [
    # a cube's own patch said without its colour (a red or a gray patch had been made up)
    ("Put the blue cube on the same coloured patch.", ["on_patch(blue,patch:blue)"]),
    ("Put the green cube on the patch that matches it.", ["on_patch(green,patch:green)"]),
    ("Put the green cube on its own patch.", ["on_patch(green,patch:green)"]),
])
def test_a_cube_s_own_patch_is_its_colour(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # spoken self-corrections (stranger25): refused over "no"/"wait" before, or read with the corrected words
    ("right so put four cubes, no wait, five cubes in a pile in the middle", ["pile(blue,green,orange,red,yellow)@center"]),
    ("uh the white one goes in front of, no sorry, behind the yellow one", ["behind(white,yellow)"]),
    ("um so put the red, no, the orange one on top of the blue one", ["stack(blue,orange)"]),
    ("put the cyan cube to the left of the, wait, to the right of the purple cube", ["right_of(cyan,purple)"]),
    # a pause "er" between commas is no list comma (pink had become the second cube of four, not the top)
    ("okay um stack four cubes and make the bottom one brown and the top one, er, pink", ["stack(brown,red,blue,pink)"]),
    ("stack red, um, blue and green", ["stack(red,blue,green)"]),
])
def test_spoken_corrections_and_pauses(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # each colour's own count (both piles had taken the first count: 3 blue cubes for "2 blue")
    ("build 2 piles: 3 red in one, 2 blue in the other", ["piles(blue,blue,red,red,red;by=color)"]),
    ("separate the 3 red and 3 blue cubes into piles", ["piles(blue,blue,blue,red,red,red;by=color)"]),  # (3 piles before)
    ("a pile of red and blue and a pile of green", ["pile(blue,red)", "pile(green)"]),
])
def test_piles_keep_each_colour_s_count(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    ("put one cube on each patch", "does not say how many patches"),  # (3 gray patches had been made up)
    ("Place one cube on each patch: red on the red patch, blue on the blue patch.", "say each cube's patch once"),
])
def test_each_patch_without_a_count_is_refused(text, words):
    with pytest.raises(ParseError, match=re.escape(words)):
        parse(text)


@pytest.mark.parametrize("text", ["tower of three, blue at the bottom, other two don't matter",
                                  "stack the pink, the blue, and the gray, doesn't matter which order"])
def test_words_leaving_the_rest_free_are_no_negation(text):
    assert type(parse(text).goal).__name__ in ("UnorderedStack", "AnchoredStack")


@pytest.mark.parametrize("text,expected", [
    # benchmark spec lines (stranger25): calls, filled template slots, identifiers with parameters
    ("place_on_patch(obj=red cube, target=blue patch)", ["on_patch(red,patch:blue)"]),
    ("in-front-of(obj=brown, ref=gray)", ["in_front_of(brown,gray)"]),
    ("put-block-in-region: block=purple, region=front-right", ["in_region(purple,front_right)"]),
    ("rearrange: move the {orange} block to the right of the {gray} block", ["right_of(orange,gray)"]),
    ("put the {dragged_obj: green cube} into the {base_obj: brown patch}", ["on_patch(green,patch:brown)"]),
    ("spell-word [word=SUN]: letter cubes in a row, left-to-right",
     ["line[left_to_right](S,U,N)", "reads(S,U,N;direction=left_to_right,face=up,text=SUN)"]),
    ("pile-5 [region=back]: put five brown cubes in one pile", ["pile(brown,brown,brown,brown,brown)@back"]),
    ("[eval] stack_3_ordered: top=orange, middle=white, bottom=black", ["stack(black,white,orange)"]),
    ("stack-two (seed 7): green cube on top of purple cube", ["stack(purple,green)"]),
    # a row said role by role (its "left" had been read as a cube picked by where it stands now)
    ("row-3: leftmost=cyan, middle=pink, rightmost=brown", ["line[left_to_right](cyan,pink,brown)"]),
    ("row of 3 going left to right: red first, green middle, blue last", ["line[left_to_right](red,green,blue)"]),
])
def test_benchmark_spec_lines(text, expected):
    assert meaning(parse(text)) == expected


def test_an_identifier_s_glued_count_is_kept():
    """"stack-any-4: blocks any, order any" had dropped the 4 and made up a stack of two."""
    schema = parse("stack-any-4: blocks any, order any")
    assert len(schema.assets) == 4 and type(schema.goal).__name__ == "UnorderedStack"


@pytest.mark.parametrize("text,expected", [
    # walls said row by row (the counts had been lost and a wall two wide made up, then refused)
    ("Can you make a wall for me? The bottom row is four orange cubes and the top row is four red cubes.",
     ["wall(orange,orange,orange,orange|red,red,red,red)"]),
    ("build a wall, two rows, bottom is three brown cubes and the top is three orange", ["wall(brown,brown,brown|orange,orange,orange)"]),
    ("build-wall: 2 rows x 3 cubes, all gray", ["wall(gray,gray,gray,gray,gray,gray)"]),  # (a grid before: the label's wall lost)
    # a structure named in a sentence of its own, its parts in the next ("in the middle" had been the table's centre)
    ("build a pyramid. Three cubes on the bottom, two in the middle and one on top", ["pyramid(red,red,red,red,red,red)"]),
    # a cube taken off the start's tower and left on the table
    ("start: yellow sitting on red. take the yellow off and leave it on the table", ["on_table(yellow)", "start:stack(red,yellow)"]),
])
def test_walls_by_rows_headings_and_take_off(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # a hostile tester's silent errors in this session's features
    ("put the red, er, orange cube on the blue one", ["stack(blue,orange)"]),  # (both cubes kept)
    ("put the red cube on the blue cube, no, the green cube on the blue cube", ["stack(blue,green)"]),  # (red kept on top)
    ("put the blue cube on the red patch, no wait, the yellow one", ["on_patch(blue,patch:yellow)"]),  # (a yellow cube)
    ("make a tower of red, green and blue, no wait, of red, green and purple", ["stack(red,green,purple)"]),  # (five cubes)
    ("stack_on(obj=red cube, base=blue cube)", ["stack(blue,red)"]),  # (reversed)
    ("place {obj: green cube} on {patch: yellow}", ["on_patch(green,patch:yellow)"]),  # (on a yellow cube)
    ("pile-5 [region=back]: pile red cubes", ["pile(red,red,red,red,red)@back"]),  # (three)
    ("stack-any-4: stack cubes", ["stack(red,blue,green,yellow)"]),  # (two)
])
def test_attack_on_corrections_and_spec_lines(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    ("[eval] stack_3_ordered: top=orange, middle=white", "do not give every cube"),  # (white on orange)
    ("[eval] stack_4_ordered: top=orange, second=white, third=red, bottom=black", "do not give every cube"),  # (two dropped)
    ("[eval] stack_3_ordered: top=orange, middle=white, bottom=black, extra=red", "no place in the tower"),  # (red on top)
    ("stack-any-4", "neither a digit cube nor a count"),  # (a stack of two)
    ("make a row: red first, green middle, blue last", "could not parse"),  # (an unordered line: the order dropped)
    ("make a tower: red bottom, blue top, other two don't matter", "counts the other cubes"),  # (two cubes)
])
def test_attack_on_spec_lines_is_refused(text, words):
    with pytest.raises(ParseError, match=re.escape(words)):
        parse(text)


def test_which_one_at_the_bottom_leaves_the_order_free():
    assert type(parse("stack red green blue, doesn't matter which one's at the bottom").goal).__name__ == "UnorderedStack"


@pytest.mark.parametrize("text,expected", [
    ("line up white gray black from left to right", ["line[left_to_right](white,gray,black)"]),  # three colours, no commas
    ("stack em all up: red green blue yellow, red first", ["stack(red,green,blue,yellow)"]),  # (a fifth cube, red)
])
def test_colour_runs_are_lists(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    ("spell HAT from left to right at the back of the table",  # a spelled word in a place (its word had been lower-cased)
     ["line[left_to_right](H,A,T)@back", "reads(H,A,T;direction=left_to_right,face=up,text=HAT)"]),
    ("orange -> front-left, purple -> back-right", ["in_region(orange,front_left)", "in_region(purple,back_right)"]),
    ("multi-goal: (1) red -> left region (2) blue -> right region (3) yellow on green patch",
     ["in_region(blue,right)", "in_region(red,left)", "on_patch(yellow,patch:green)"]),
])
def test_words_in_places_and_arrows_to_places(text, expected):
    assert meaning(parse(text)) == expected


def test_a_run_of_labels_with_an_end_keeps_every_label():
    """The middle digit had been dropped (stack(1,3)).  (Label cubes keep their listed order: the
    steering states anchored stacks of coloured cubes only.)"""
    assert meaning(parse("stack the digits 1 to 3, 1 at the bottom")) == ["stack(1,2,3)"]


@pytest.mark.parametrize("text,expected", [
    # stranger26's silent errors (read after its first run): a cube put in a place after a tower had joined the tower
    ("build a tower of purple, orange and white from bottom to top. Then put a brown cube in the back left corner",
     ["in_region(brown,back_left)", "stack(purple,orange,white)"]),
    ("stack blue on red, then white cube to the front left corner", ["in_region(white,front_left)", "stack(red,blue)"]),
    ("TODO(me): sort digit cubes 8, 3, 6 right-to-left ascending", ["line[right_to_left](3,6,8)"]),  # (left to right)
    ("TODO: three piles by colour - red, green, blue, 2 each", ["piles(blue,blue,green,green,red,red;by=color)"]),  # (3 each)
])
def test_stranger26_silent_errors(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # stranger24/26/27 silent errors (nineteenth session): arrows for directions had been dropped ("l->r")
    ("digits 1-4 sorted l->r", ["line[left_to_right](1,2,3,4)"]),
    ("3 cubes in a row L->R: red, yellow, green", ["line[left_to_right](red,yellow,green)"]),
    ("tower red, green, blue (t->b)", ["stack(blue,green,red)"]),
    # "blk" as an item of an arrowed list had been dropped with the black cube
    ("blk -> wht -> gry tower (bottom first)", ["stack(black,white,gray)"]),
    # a config line's count had been dropped (a circle of six, a tower of two)
    ("layout: circle, n_cubes: 5, colors: any", ["circle(red,red,red,red,red)"]),
    # "patch red, purple on ...": the red patch, then a new clause (a gray patch and a red cube had been made up)
    ("Cyan on patch red, purple on patch red also.", ["on_patch(cyan,purple,patch:red)"]),
    ("Stack of pink cubes, three pink, on the right part of table.", ["stack(pink,pink,pink)@right"]),
    ("Goal state: two separate towers, one of two red cubes and one of two blue cubes.",
     ["stack(blue,blue)", "stack(red,red)"]),
    # roles said tersely, in any order, with the middle counted
    ("Stack tower, 4 layer, bottom layer purple, top layer yellow, middle two layer both white.",
     ["stack(purple,white,white,yellow)"]),
    ("a tower of 4: bottom purple, top yellow, middle two white", ["stack(purple,white,white,yellow)"]),
    ("note to self: pyramid 3-2-1, bottom all white, middle both gray, top black", ["pyramid(white,white,white|gray,gray|black)"]),
    # "down" and "up" as a tower's ends and a wall's rows (literal translations)
    ("a tower of yellow, blue and cyan - yellow down, cyan up", ["stack(yellow,blue,cyan)"]),
    ("I want wall: down row gray gray gray, up row black black black.", ["wall(gray,gray,gray|black,black,black)"]),
    # "on it" after a cube put on a patch: on that cube
    ("Put the white cube on the gray patch and stack the red cube on it.", ["on_patch(white,patch:gray)", "stack(white,red)"]),
    # labels listed as they start and as they end: the end order (the start order had been the goal's)
    ("You should see the number cubes 5, 2, 8 rearranged so they go 2, 5, 8 from left to right.", ["line[left_to_right](2,5,8)"]),
])
def test_nineteenth_session_silent_errors(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    ("tower, n cubes: 3", "'3'"),  # a number after a colon that no count of the task carries
    ("foo, white, gray tower", "'foo'"),  # an unknown word as an item of a list of colours
    ("In the final picture the red cube is next to the green patch and the yellow cube is on it.", "'on it'"),
    ("put the red cube next to the blue patch and the green cube behind it", "'behind it'"),
    ("Have the gripper put the cube it just dropped on the green patch.", "'it just dropped'"),  # an earlier event
    ("the number cubes 5, 2, 8 rearranged so they go 2, 5, 9 from left to right.", "lists other labels"),
    # "all C cubes" without an article names several cubes (it had been read as one cube in a side relation)
    ("all red cubes on the left, all blue cubes on the right", "'all red cubes' names several red cubes"),
])
def test_nineteenth_session_refusals(text, words):
    with pytest.raises(BadInput, match=re.escape(words)):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # a caption of the finished scene, the robot as the subject, and exclaimed asides (stranger27's voices)
    ("You should see three gray cubes heaped together in the middle of the table.", ["pile(gray,gray,gray)@center"]),
    ("The image shows the pink cube far away from the blue cube.", ["far_from(blue,pink)"]),
    ("The gripper should stack the cyan cube on the pink cube.", ["stack(pink,cyan)"]),
    ("Have the gripper stack the cyan cube on the pink cube.", ["stack(pink,cyan)"]),
    ("The robot arm is to place the white cube in front of the orange cube.", ["in_front_of(white,orange)"]),
    ("Put the green block on the purple block. What a tower!", ["stack(purple,green)"]),
    ("Put the white block far away from the black block. They need some space!", ["far_from(black,white)"]),
])
def test_captions_robot_subjects_and_asides(text, expected):
    assert meaning(parse(text)) == expected


def test_an_exclaimed_sentence_that_says_something_stays():
    with pytest.raises(BadInput, match="big"):  # a size is refused, not dropped as an aside
        parse("Put the green block on the purple block. Use the big one!")
    assert meaning(parse("Put the green block on the purple block. Then put the red block on the green block!")) == [
        "stack(purple,green,red)"]


@pytest.mark.parametrize("text,expected", [
    # stranger26's headings and framings (nineteenth session): a student's "Design a task ...", a note's heading before
    # a dash or an arrow, capitals of a note, a measure word, "not important", "from minor to major", "rest whatever"
    ("Design a task where the robot must put the pink cube in the back right corner of the table.",
     ["in_region(pink,back_right)"]),
    ("Design a task; the robot puts the red cube between the green patch and the blue patch.",
     ["between(red;patch:blue,patch:green)"]),
    ("new task -> red cube in the middle of the table", ["in_region(red,center)"]),
    ("ticket 88 - robot should line up the green, black and gray cubes front to back in that order",
     ["line[front_to_back](green,black,gray)"]),
    ("TODO eval set: \"orange on top of cyan\" and \"purple right of gray\"", ["right_of(purple,gray)", "stack(cyan,orange)"]),
    ("Please use 3 piece green cube make one tower.", ["stack(green,green,green)"]),
    ("The robot must to order the cubes of numbers 7, 2, 5 from minor to major, of left to right.",
     ["line[left_to_right](2,5,7)"]),
    # a structure word before a heading's colon is the task's (the wall had become a grid)
    ("Task 5 - wall: 2 rows of 4 cubes, all yellow.", ["wall(yellow,yellow,yellow,yellow,yellow,yellow,yellow,yellow)"]),
    # a "2x3" wall said with a bottom and a top row is two rows of three (a middle row had been made up)
    ("todo - wall 2x3: bottom row orange, top row yellow", ["wall(orange,orange,orange|yellow,yellow,yellow)"]),
])
def test_stranger26_headings_and_framings(text, expected):
    assert meaning(parse(text)) == expected


def test_colours_said_unimportant_leave_them_free():
    schema = parse("Make from the six cubes a pyramid, and the colours are not important.")
    assert matches("pyramid(?,?,?,?,?,?)", meaning(schema))


def test_the_rest_left_free_needs_a_count():
    assert matches("stack(pink,?,?)", meaning(parse("new task -> tower of three, pink bottom, rest whatever")))
    with pytest.raises(BadInput, match="does not say how many cubes"):
        parse("a tower, pink bottom, rest whatever")


@pytest.mark.parametrize("text,expected", [
    # stranger27's remaining classes (nineteenth session)
    ("Have the robot make a row of four cubes from left to right; the first is white, the last is black, and the two in "
     "the middle are gray.", ["line[left_to_right](white,gray,gray,black)"]),
    ("Make a line of cubes from the front of the table to the back: green first, then white, then black last.",
     ["line[front_to_back](green,white,black)"]),
    ("# done when the green block is far from the red block", ["far_from(green,red)"]),
    ("# reward = 1 iff the black cube is in front of the white cube", ["in_front_of(black,white)"]),
    ("Level 4 objective: the black cube should sit directly to the right of the white cube.", ["right_of(black,white)"]),
    ("Level 3: Place the cyan cube on the yellow patch and the pink cube on the purple patch. Time: unlimited.",
     ["on_patch(cyan,patch:yellow)", "on_patch(pink,patch:purple)"]),
    ("Design a task where the robot must build two towers: tower A is green on brown; tower B is pink on gray.",
     ["stack(brown,green)", "stack(gray,pink)"]),
    ("stack two red cubes and two blue cubes reds at the bottom", ["stack(red,red,blue,blue)"]),
    ("task 22: build two towers of 2 - reds in one, yellows in the other", ["stack(red,red)", "stack(yellow,yellow)"]),
    ("Puzzle #12: Make a pyramid with a base of three black cubes, two gray cubes above them and one white cube at the summit.",
     ["pyramid(black,black,black|gray,gray|white)"]),
    ("um okay so line up the number cubes one two three four five from left to right", ["line[left_to_right](1,2,3,4,5)"]),
])
def test_stranger27_remaining_classes(text, expected):
    assert meaning(parse(text)) == expected


def test_a_colour_said_as_a_plural_noun_is_its_cubes():
    """"the reds" had been an unknown word (refused); it is every red cube, as "the red ones" is."""
    schema = parse("Group the cubes by colour: the reds together on the red patch, the yellows together on the yellow patch.")
    assert matches("on_patch(red*,patch:red); on_patch(yellow*,patch:yellow)", meaning(schema))


def test_the_middle_two_left_free_and_trailers_dropped():
    schema = parse("Challenge: build a four-cube tower with red on the bottom and blue on top. The middle two can be anything. "
                   "Bonus: none.")
    assert matches("stack(red,?,?,blue)", meaning(schema))


@pytest.mark.parametrize("text,words", [
    ("a row of four cubes; the first is white, the last is black, and the two in the middle are gray.", "'last'"),  # no direction
])
def test_stranger27_refusals(text, words):
    with pytest.raises(BadInput, match=re.escape(words)):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # stranger28's silent errors: a terse end after a list had been a fourth cube; a height after the colour and a
    # count as a multiplier had been dropped (a tower of two, a circle of six)
    ("tower: red/white/orange, red bottom", ["stack(red,white,orange)"]),
    ("Buld a tower of grey cubes, three high.", ["stack(gray,gray,gray)"]),
    ("circle x5, all orange", ["circle(orange,orange,orange,orange,orange)"]),
])
def test_stranger28_silent_errors_read(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,words", [
    ("stack red on blue, 3 high", "'3 high' asks for a structure 3 cubes high"),  # a height no reading carries
    ("put the red cube on the blue cube x3", "3 blue"),
])
def test_a_height_or_multiplier_the_task_lacks_is_refused(text, words):
    with pytest.raises(BadInput, match=re.escape(words)):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Not a pyramid, a tower: red at the bottom, then blue, then white on top.", ["stack(red,blue,white)"]),
    ("not descending, ascending: digit cubes 2, 4, 6 and 8 in a row, lowest on the left",
     ["line[left_to_right](2,4,6,8)"]),  # the denied order had been read as the order
    ("Not left of it, right of it: the pink cube goes to the right of the gray cube.", ["right_of(pink,gray)"]),
    ("Not the back left corner, the front right corner: put the black cube there.", ["in_region(black,front_right)"]),
    ("I don't want a tower here; I want a line of three cubes, orange, cyan and pink, from left to right.",
     ["line[left_to_right](orange,cyan,pink)"]),
    ("The goal isn't to stack them. The goal is to put the yellow cube on the red patch and the blue cube on the green "
     "patch.", ["on_patch(blue,patch:green)", "on_patch(yellow,patch:red)"]),
    ("It is not the blue patch, it is the white patch: the cyan cube goes on the white patch.", ["on_patch(cyan,patch:white)"]),
    ("not two towers, one tower with all four: green, green, yellow, yellow from the bottom up",
     ["stack(green,green,yellow,yellow)"]),
])
def test_a_denied_alternative_beside_the_meant_one_is_dropped(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "Put the red cube on the blue patch, not next to the green cube.",  # a second constraint, denied: not a contrast
    "Put the red cube left of the blue cube, not behind the green cube.",
    "The orange cube must not be next to the purple cube.",
    "Not a tower. Put the red cube next to the blue cube.",  # no alternative of the same kind beside the denial
])
def test_a_denial_of_anything_else_stays_refused(text):
    with pytest.raises(BadInput, match="negation"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Build a pyramid from six cubes, colours of your choosing.", "pyramid(?,?,?,?,?,?)"),
    ("tower of 5 green cubes, thats the whole task", "stack(green,green,green,green,green)"),
    ("imo the cleanest task: red cube left of blue cube. nothing else", "left_of(red,blue)"),
    ("There should be three cubes in the end, all in the front half of the table: a red one, a blue one and a green one. "
     "How they are arranged inside that front half does not matter.", "in_region(blue,front); in_region(green,front); "
                                                                      "in_region(red,front)"),
    ("For the demonstration, the pink cube has to be put on top of the brown cube. After that, the brown-and-pink stack "
     "should be standing on the yellow patch.", "stack(brown,pink); on_patch(brown,patch:yellow)"),
    ("I am picturing a tidy table with the cubes sorted into piles by their colour. There are two cyan cubes, two whte "
     "cubes and two black cubes, and each colour should get its own pile.", "piles(black,black,cyan,cyan,white,white;by=color)"),
])
def test_freedom_closings_and_pictures_said_in_other_words(text, expected):
    assert matches(expected, meaning(parse(text)))


@pytest.mark.parametrize("text,expected", [
    # a colour's cube said again with "a": one more cube (the second had been the first, put on two patches, refused)
    ("A grey cube on the blue patch and a grey cube on the red patch, if you please.",
     ["on_patch(gray,patch:blue)", "on_patch(gray,patch:red)"]),
    ("orange @ front right corner", ["in_region(orange,front_right)"]),  # a terse spec's "@"
    ("put the green block b/w the red and blue ones. thats it", ["between(green;blue,red)"]),
    ("The end state requires the gray block to be adjacent to the orange block.", ["next_to(gray,orange)"]),
    ("lowkey just need two piles, 3 red cubes in one and 3 blue in the other",
     ["piles(blue,blue,blue,red,red,red;by=color)"]),
])
def test_stranger28_terse_and_repeated_mentions(text, expected):
    assert meaning(parse(text)) == expected


def test_a_repeated_cube_said_with_the_stays_one_reading():
    """"a red cube ... the red cube" is one cube; the "another" reading applies only where no "the" names it."""
    schema = parse("Put a red cube on the blue patch, then put the green cube on the red cube.")
    assert sum(a.color == "red" for a in schema.assets) == 1


@pytest.mark.parametrize("text", [
    "From the camera, the red cube should be to the left of the green cube.",
    "On your left, the yellow cube; on your right, the purple cube.",
    "As you face the table, put the green cube at the left end of a row and the pink cube at the right end.",
    "From the camera, the white cube should be further away than the black cube, i.e. behind it.",
])
def test_a_viewer_other_than_the_robot_is_refused_naming_the_robots_frame(text):
    """The snapshot camera shares the robot's left, the agentview camera mirrors it: another viewer's side is unknown."""
    with pytest.raises(BadInput, match="viewer other than the robot"):
        parse(text)


def test_the_robots_own_viewpoint_is_read():
    assert meaning(parse("Seen from the robot, the red cube should be to the left of the green cube.")) == ["left_of(red,green)"]


@pytest.mark.parametrize("text", [
    # a hostile tester's silent errors of this session's features and older ones they uncovered: each now refused
    "Put the red cube on the blue patch rather than next to the green cube.",  # had asserted the denied relation
    "Put the red cube left of the blue cube instead of left of the green cube.",
    "Put the red cube right of the blue cube, not left of the green cube.",  # another cube's denial had been dropped
    "Put the red cube on the blue cube, not under the green cube.",
    "Put the black cube on the left side, not in the back left corner.",  # overlapping places are no contrast
    "Put the red cube in the back half, not in the back left corner.",
    "Picture three towers of two cubes. Now make only one of them.",  # some of a group described earlier
    "Make a tower of gray cubes, 3 high, and another one.",
    "Let me describe the goal. Red on blue. Let me describe the start: green on yellow.",  # the start is no label
    "For the demonstration, stack red on blue; for the evaluation, stack green on yellow.",
    "I am picturing the red cube somewhere near the blue one, maybe on it.",  # a hedge between two goals
    "Think of a row of red, green and blue from left to right, but build it from right to left.",
    "The end state requires the red cube on the blue cube?",
    "Here is the setup I want to evaluate: the robot starts with red on blue and must put red on the green patch.",
    "Make a tower of gray cubes, 3 wide.",  # a length no reading carries
    "Make a tower of gray cubes, 3 high, times two.",  # repetitions
    "Make a circle x5 x2.",
    "Make a circle of 6 cubes, red and blue alternating.",  # InCircle checks no order round the circle
    "Put the red cube on the red patch and the blue cube on the blue patch; which goes where is your call.",
    "Line up red, green and blue from left to right. How they are arranged does not matter.",
    "Make a red tower of three cubes. Colours of the cubes are not specified.",
    "Put the red cube on the blue patch. There are no patches involved.",
])
def test_attacks_on_contrasts_freedom_framing_and_counts_are_refused(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Make a tower of gray cubes, 3 levels.", ["stack(gray,gray,gray)"]),
    ("Make a row of gray cubes, 3 long.", ["line(gray,gray,gray)"]),
    ("Make 3 towers x2 high of gray cubes.", ["stack(gray,gray)", "stack(gray,gray)", "stack(gray,gray)"]),
    ("Put a red cube on the blue patch, i.e. a red cube must end up on the blue patch.", None),  # one cube, said twice
    ("Build a wall of red cubes, four wide and two high.", ["wall(red,red,red,red,red,red,red,red)"]),
])
def test_heights_lengths_and_restatements_read(text, expected):
    if expected is None:
        with pytest.raises(BadInput, match="twice"):
            parse(text)  # restated, not a second red cube (it had become two)
    else:
        assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text,expected", [
    # stranger29's silent errors: an end said as "the bottom one" had been put at the top; "the numbers go down" had kept
    # the listed order
    ("Build a tower of three cubes. The green cube must be the bottom one.", "stack(green,?,?)"),
    ("Challenge: place the digit cubes 6, 2, 9 and 4 in a row so that the numbers go down from left to right.",
     "line[left_to_right](9,6,4,2)"),
    ("place the digit cubes 6, 2, 9 and 4 in a row so that the numbers go up from left to right.",
     "line[left_to_right](2,4,6,9)"),
])
def test_stranger29_silent_errors_read(text, expected):
    assert matches(expected, meaning(parse(text)))


def test_one_cube_at_both_ends_is_a_contradiction():
    with pytest.raises(BadInput, match="both ends"):
        parse("Stack the white cube and the black cube so that the white cube is both at the bottom and at the top.")


def test_steering_corrections_with_instead_of_still_read():
    """'instead of' denies only where it names another cube or place ('rather than next to the green cube'); an
    edit's 'instead of on top' corrects the relation, and 'instead of coloured ones' swaps the material."""
    parse("Put the red cube next to the blue cube instead of on top.")
    with pytest.raises(BadInput, match="negation"):
        parse("Put the red cube on the blue patch rather than next to the green cube.")


def test_a_second_indefinite_cube_of_a_colour_is_another_cube():
    """"a pink cube on the table, a cyan cube on it, and then a pink cube on the cyan one": two pink cubes (it had been
    refused as one pink cube said twice)."""
    assert meaning(parse("Place a pink cube on the table, put a cyan cube on it, and then a pink cube on the cyan one.")) == [
        "stack(pink,cyan,pink)"]


@pytest.mark.parametrize("text", [
    "Alright, let's do something fun: a circle made of six cubes, alternating orange and green.",
    "circle of six cubes alternating red and white",
])
def test_alternating_colours_round_a_circle_are_refused(text):
    """InCircle judges where the cubes stand round the circle, not their order: the alternation had been dropped."""
    with pytest.raises(BadInput, match="not their order round it"):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    # RFC-style capitals, endearments, Indian and Singapore English closings, the robot's frame said in passing
    ("The red cube MUST be stacked on the blue cube. The green cube SHALL be placed on top of the red cube.",
     ["stack(blue,red,green)"]),
    ("Let's make a tall tower, honey: the green one first at the bottom, then the blue one, then the pink one at the very "
     "top!", ["stack(green,blue,pink)"]),
    ("Put the purple cube on the white patch one time.", ["on_patch(purple,patch:white)"]),
    ("Put the red cube to the right of the blue cube (right as seen from the robot).", ["right_of(red,blue)"]),
    ("Spell NOT with the letter cubes.", ["line[left_to_right](N,O,T)", "reads(N,O,T;direction=left_to_right,face=up,text=NOT)"]),
])
def test_stranger29_voices_read(text, expected):
    assert meaning(parse(text)) == expected


def test_a_negation_in_capitals_is_a_negation():
    """A capital NOT had passed as a word to spell and been refused only as an unplaced capital."""
    with pytest.raises(BadInput, match="negation"):
        parse("The purple cube MUST NOT be next to the cyan cube.")


@pytest.mark.parametrize("text", [
    # a second hostile tester's silent errors of this session's readings (and older ones next to them): refused now
    "The red cube MAY be on the blue patch.",  # a capital MAY had been a requirement
    "The red cube MUST be on the blue cube OR on the green cube.",  # a capital OR had become a three-cube tower
    "Put the red cube left of the blue cube (right as seen from the robot).",  # a conflicting viewpoint had been dropped
    "a tower of red, blue (bottom), yellow",  # an end on a middle cube
    "red (bottom), blue, yellow (bottom)",
    "Build four towers of one cube.",  # had been four towers of four
    "two towers of three cubes of different colours",  # had been all red
    "Put the red, green and blue cubes next to each other.",  # a chain had been made up
])
def test_second_attack_classes_are_refused(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text,expected", [
    ("Stack the red, blue and green cubes; the green cube must be the top one and the red cube the bottom one.",
     ["stack(red,blue,green)"]),  # a listed colour's end is not one more cube
    ("Build a tower of red (top), blue, yellow.", ["stack(yellow,blue,red)"]),  # had been reversed
    ("new eval task -> stack: white (bottom) / red / white (top)", ["stack(white,red,white)"]),
    ("Make two piles of three blocks, one of red blocks and one of blue blocks.", ["piles(blue,blue,blue,red,red,red;by=color)"]),
    ("Place the two black cubes next to each other and the white cube far from them.",
     ["far_from(black,white)", "far_from(black,white)", "next_to(black,black)"]),  # a tower had been made up for "them"
])
def test_second_attack_classes_read(text, expected):
    assert meaning(parse(text)) == expected


def test_a_goal_opened_twice_after_a_start_is_read():
    """"Task: unstack it so that ...": the label and the unstacking both open the goal (only the label had been taken)."""
    assert meaning(parse("Initial state: the red cube sits on the green cube. Task: unstack it so that the red cube is on "
                         "the table.")) == ["on_table(red)", "start:stack(green,red)"]


# ---------------------------------------------------------------------------
# twenty-first session: framing sentences, sentences no reader read, coordinated relations
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("text, expected, framing", [
    ("Quick one today, folks - the goal is just to put the orange cube in the back right corner of the table. "
     "Code is linked in the description.", ["in_region(orange,back_right)"], "Code is linked in the description."),
    ("Okay, operator, here's the task: pick up the blue cube and put it on the red patch. Go when ready.",
     ["on_patch(blue,patch:red)"], "Go when ready."),
    ("Stack the red cube on the blue cube. Start recording.", ["stack(blue,red)"], "Start recording."),
])
def test_a_sentence_said_to_a_person_that_names_nothing_of_the_task_is_dropped_and_listed(text, expected, framing):
    from rpg.schema.reading import normalize_words

    assert meaning(parse(text)) == expected
    _, _, dropped = normalize_words(text)
    assert (framing, "a sentence that names nothing of the task") in dropped


@pytest.mark.parametrize("tail", [
    "Rotate.", "Lift it.", "And the opposite.", "Then drop.", "Tidy up.", "Alternate.", "Wobbly.", "Loosely.",
    "Return everything.", "Beneath, I mean.", "Then reset.", "Hold it there.", "Facing me.", "Vertically.", "Sorted.",
    "Demolish it afterwards.", "Do it twice.", "Upside down.", "Swap them.",
])
def test_a_sentence_that_may_change_the_task_and_that_no_reader_read_is_refused(tail):
    """Before the sentence check, a trailing sentence of known words that no reader read was ignored ("Stack the red
    cube on the blue cube. Rotate." compiled to the stack alone): every sentence must now hold something of the task,
    or be framing said to a person."""
    with pytest.raises(ParseError):
        parse(f"Stack the red cube on the blue cube. {tail}")


@pytest.mark.parametrize("text", [
    "Make a tower out of the red, white and black cubes. Any order is fine.",
    "Riddle for the robot: the green cube is left of the pink cube, and the pink cube is left of the gray cube. Build exactly that.",
    "Stack the red block on the blue block. My supervisor wants this for the demo.",
    "Wall: bottom row three grey blocks, top row three brown blocks. Put it at the back of the table.",
])
def test_sentences_that_restate_or_free_the_goal_are_part_of_the_task(text):
    parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Put the red cube far away from the blue cube but next to the green cube.", ["far_from(blue,red)", "next_to(green,red)"]),
    ("put red left of blue but near green", ["left_of(red,blue)", "next_to(green,red)"]),
    ("put red next to blue but far from green", ["far_from(green,red)", "next_to(blue,red)"]),
    ("Put the red cube far from the blue one but next to the green one.", ["far_from(blue,red)", "next_to(green,red)"]),
])
def test_a_relation_after_but_keeps_the_clause_subject(text, expected):
    """"X far from Y but next to Z": X is next to Z (it had been Y next to Z, silently wrong)."""
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Please make a tower of two cubes, the white cube at the top and the same white cube also at the bottom.",
    "Three-cube tower with the black cube at the bottom and the same black cube on top.",
])
def test_the_same_coloured_cube_given_a_second_place_is_a_contradiction(text):
    with pytest.raises(Inexpressible) as err:
        parse(text)
    assert err.value.kind == "contradiction"


@pytest.mark.parametrize("text, expected", [
    ("Level 4 card: put the red block between the yellow patch and the green patch, and put the blue block on the green "
     "patch.", ["between(red;patch:green,patch:yellow)", "on_patch(blue,patch:green)"]),
    ("Challenge: Wall Builder. Build a wall that is three blocks long and two blocks high, bottom row all brown, top row "
     "all orange.", ["wall(brown,brown,brown|orange,orange,orange)"]),
    ("CHALLENGE 2 - Tower Rush. Goal: a four-block tower, order from the bottom: green, cyan, blue, purple.",
     ["stack(green,cyan,blue,purple)"]),
    ("== Task 4 == Stack the pink cube on the orange cube.", ["stack(orange,pink)"]),
    ("Realise a pyramid with three blue cubes at the base, two red cubes above, and one yellow cube at the summit.",
     ["pyramid(blue,blue,blue|red,red|yellow)"]),
])
def test_titles_headings_and_verbs_of_other_englishes(text, expected):
    """A capitalised title whose task words the text says again, a numbered heading before a colon, a wiki's
    "== heading ==", and "realise"/"chuck" as build/put."""
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", ["Upside Down. Stack red on blue.", "Quickly Now. Stack red on blue.",
                                  "Stack Them Twice. Stack red on blue."])
def test_a_title_that_may_change_the_task_is_not_dropped(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text", [
    # a follow-up relation with no cube (a hostile tester's class A): it had been read as nothing
    "Put the red block left of the blue block. Okay, right of it.", "Put the red block on the blue block. Under it.",
    "Put the red block on the blue block. Below it, actually.", "Put the red block in front of the blue block. Behind it.",
    # a reversal read by nothing (class B): the order said before had been kept
    "Put the red block on the blue block. Then flip the tower.", "Put the red block on the blue block, reversed.",
    "Put the red block on the blue block. Reverse the order of the blocks.",
    "Make a row: red, green, yellow, left to right, but reversed.", "Put the red block on the blue block in reverse order.",
    # an alternative left over (class C): both goals had been kept
    "Instead of putting the red block next to the blue block, put the green block on the yellow block.",
    "Put the red block next to the blue block. Instead, put the green block on the yellow block.",
])
def test_corrections_reversals_and_alternatives_no_reader_reads_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Stack the red cube, the white cube, the yellow cube in the reversed order", ["stack(yellow,white,red)"]),
    ("Sort the letters Z, Y and X in reverse alphabetical order, left to right.", ["line[left_to_right](Z,Y,X)"]),
    ("Put the red cube next to the blue cube instead of on top.", ["next_to(blue,red)"]),
    ("User: put the yellow cube between the green and the pink cubes. Assistant: On it.", ["between(yellow;green,pink)"]),
    ("Put the red and orange blocks far from the blue block but next to the green block.",
     ["far_from(blue,orange)", "far_from(blue,red)", "next_to(green,orange)", "next_to(green,red)"]),
])
def test_reversals_alternatives_and_replies_the_readers_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    ("The red cube starts on top of the blue cube. Unstack it and leave both cubes on the table.",
     ["on_table(blue)", "on_table(red)", "start:stack(blue,red)"]),
    ("Start with a tower of green (bottom), yellow, white (top). Take it apart so that every cube stands on the table.",
     ["on_table(green)", "on_table(white)", "on_table(yellow)", "start:stack(green,yellow,white)"]),
])
def test_a_start_said_with_start_with_or_starts_on_then_taken_apart(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", ["Put the red block next to the green block but on the blue patch.",
                                  "Put the red block next to the green block and on the blue patch.",
                                  "Put the red block far from the green block but on the blue patch."])
def test_a_patch_after_but_or_and_is_the_subject_s(text):
    """The subject carried over takes the patch too (the green block had been put on it, silently wrong)."""
    assert "on_patch(red,patch:blue)" in meaning(parse(text))


@pytest.mark.parametrize("text", ["Stack the red block on top of two blocks.", "Put the red block on two stacked blocks.",
                                  "Put the red block on a stack of two blocks.",
                                  "Put the red block on the blue patch and stack two blocks on it."])
def test_cubes_counted_under_or_on_a_named_cube_are_besides_it(text):
    """The count had been met by the named cube itself (a tower of two: one block lost): refused unless the task holds
    that many more."""
    with pytest.raises(ParseError, match="besides"):
        parse(text)


def test_the_colour_one_after_a_patch_is_a_patch():
    assert sorted(meaning(parse("Put the red block on the blue patch and the green block on the yellow one."))) == [
        "on_patch(green,patch:yellow)", "on_patch(red,patch:blue)"]
    assert sorted(meaning(parse("Put the red block on the blue block and the green block on the yellow one."))) == [
        "stack(blue,red)", "stack(yellow,green)"]


@pytest.mark.parametrize("text, expected", [
    ("Place four cubes on the yellow patch: two red and two blue.", ["on_patch(blue,blue,red,red,patch:yellow)"]),
    ("Build a tower of four cubes. The bottom one is black and the top one is yellow; the two in between are both blue.",
     ["stack(black,blue,blue,yellow)"]),
    ("Stack five cubes. The base is black and the top is white; the three in between are gray.",
     ["stack(black,gray,gray,gray,white)"]),
    ("Make a tower with the cyan cube at the bottom and the red cube at the top, with the blue cube between them.",
     ["stack(cyan,blue,red)"]),
])
def test_counts_broken_down_by_colour_and_a_tower_s_middle(text, expected):
    """A count then its colours after a colon; a tower's middle cubes given one colour (it had reached one of three:
    silently wrong once the middle was read as a role); "between them" in a tower whose ends are given."""
    assert meaning(parse(text)) == expected


def test_one_cube_on_top_of_another_is_two_unnamed_cubes_in_any_order():
    from rpg.domain.predicates import UnorderedStack

    assert isinstance(parse("Please put one cube on top of another.").goal_predicate(), UnorderedStack)


@pytest.mark.parametrize("text", [
    "Put the red cube on the blue patch and left of the blue patch.",
    # some of a group: which ones is not said (three had been stacked for "any two")
    "The table has a red, a green and a yellow cube. Stack any two of them.", "Stack two of the red, green and blue cubes.",
])
def test_second_session_attack_classes_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Start with the red cube on the blue cube. Move the red cube to the left of the blue cube.",
     ["left_of(red,blue)", "start:stack(blue,red)"]),
    ("Build a tower of red, green and blue, starting with blue.", ["stack(blue,red,green)"]),  # (a fourth cube had been made)
    ("Make a tower from the yellow, purple and white blocks, yellow first.", ["stack(yellow,purple,white)"]),
    ("Put the gray cube in front of the brown cube, which should be in the center.",
     ["in_front_of(gray,brown)", "in_region(brown,center)"]),
    ("Put the red cube onto the yellow spot.", ["on_patch(red,patch:yellow)"]),
])
def test_second_session_attack_classes_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_tower_s_first_cube_is_its_bottom_and_the_rest_free():
    from rpg.domain.predicates import AnchoredStack

    goal = parse("Build a tower of red, green and blue, starting with blue.").goal_predicate()
    assert isinstance(goal, AnchoredStack) and goal.bottom and not goal.top and goal.objects[0] == "blue"


@pytest.mark.parametrize("text", [
    "Place the green cube between the red cube and the blue cube, in a line.",
    "Line up the red, blue and yellow cubes with blue at one end.",
    "Place the red, green, and blue cubes in a row in reverse order.",
    "Make a row of three red cubes and two blue cubes with the blue cubes at the ends.",
    "Line up the red, blue and yellow cubes with the red cube between the other two.",
])
def test_a_place_in_a_line_that_no_reader_read_is_refused(text):
    """The line had been read in any order, the cube's place in it dropped (a goal weaker than the words)."""
    with pytest.raises(ParseError):
        parse(text)


def test_two_cubes_put_on_a_third_stand_above_it_in_any_order():
    from rpg.domain.predicates import AnchoredStack

    goal = parse("Put the red and green cubes on the blue cube.").goal_predicate()
    assert isinstance(goal, AnchoredStack) and goal.bottom and not goal.top and goal.objects[0] == "blue"


@pytest.mark.parametrize("text", [
    "Spell GO in a tower, with G at the bottom.",  # a spelled tower reads top to bottom: G had been put on top
    "There are four cubes: red, green, blue and yellow. Stack all of them into one tower.",  # a fifth had been made up
])
def test_an_end_or_a_scene_count_the_reading_contradicts_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_both_objects_of_between_stay_off_a_later_patch():
    assert sorted(meaning(parse("Put the orange cube between the red and yellow cubes, and the red cube on the purple "
                                "patch."))) == ["between(orange;red,yellow)", "on_patch(red,patch:purple)"]


@pytest.mark.parametrize("text", [
    "Put the red cube next to the green cube and then stack it on the blue cube.",  # "it" had been green, stacked under blue
    "Put the red and green cubes in one pile and the blue cube in another pile.",  # the two piles had been merged
    "Put the red block on the blue block. Then tidy up the table.",  # "tidy" had been dropped as a filler
    "Put the red block next to the blue block. The blue block should stay put.",  # the constraint had been dropped
])
def test_older_silent_classes_the_second_tester_left_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # the robot as a landmark: a region of the table (the words had been dropped with the ignorable "robot's")
    ("we want 3 pink blocks lined up left to right in front of the robot", ["line[left_to_right](pink,pink,pink)@front"]),
    ("eval task: white cube on the robot's left, black cube on the robot's right",
     ["in_region(black,right)", "in_region(white,left)"]),
    ("put the red block far from the robot", ["in_region(red,back)"]),
    ("put the red cube next to the blue cube, on its left", ["left_of(red,blue)", "next_to(blue,red)"]),  # its: the cube's
    # a layer's colour reaches every cube of it (one red cube had been put at the bottom, two made up)
    ("Build a 3-2-1 pyramid with red on the bottom layer, green in the middle layer and blue on top.",
     ["pyramid(red,red,red|green,green|blue)"]),
])
def test_places_said_by_the_robot_and_layers_said_by_colour_are_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    ("Stack-3-Ordered: agents must build a tower with blue at the base, green in the middle and red at the top. "
     "Ranked by success rate over 100 episodes.", ["stack(blue,green,red)"]),
    ("Repro task: the purple block should be placed far from the pink block (fails on roughly 30% of seeds)",
     ["far_from(pink,purple)"]),
    ("Deliverable D4 describes the evaluation task, in which the robot builds a pyramid of three cubes, with two white "
     "cubes forming the base and a black cube at the apex.", ["pyramid(white,white|black)"]),
    ('Repro: 1. reset the sim 2. give the task "put the cyan cube behind the red cube" 3. the success check never fires',
     ["behind(cyan,red)"]),
    ("Build a tower with the red cube at the bottom and two more cubes of any colour on it", ["stack(red,blue,green)"]),
    ("Build a tower that is 4 blocks tall with a white block on top. The other blocks can be any colour.",
     ["stack(red,blue,green,white)"]),
])
def test_reports_on_evaluating_a_task_and_towers_said_by_one_end_are_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Stack the red cube on the blue cube. In every episode nothing else may move.",  # a constraint, not a report
    "Stack the red cube on the blue cube. Best policy so far knocks everything over.",  # a move of cubes
    "Stack the red cube on the blue cube. Run it for 5 seeds.",  # 'it' may stand for a cube
    "We never used the task where the robot stacks the red cube on the blue cube.",  # a denial before the task
    'task: "stack red on blue" but never in the corner',  # the words outside the quote say a place
    "Stack the red cube on the blue cube, the others can be any colour",  # no count: which others?
])
def test_reports_that_may_say_something_of_the_goal_are_not_dropped(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Start: red cube stacked on a white cube stacked on a black cube. Goal: take off the red cube and put it on the "
     "table; leave the other two as they are.", ["on_table(red)", "stack(black,white)", "start:stack(black,white,red)"]),
    ("Unstack the tower. It starts as blue on the bottom, then orange, then white on top, and at the end all three "
     "cubes should be on the table.", ["on_table(blue)", "on_table(orange)", "on_table(white)", "start:stack(blue,orange,white)"]),
    ("take the orange block off the brown block and set it down next to it. the orange block starts on top of the "
     "brown one", ["next_to(brown,orange)", "start:stack(brown,orange)"]),
    ("The red cube starts on the blue cube. Unstack it.", ["on_table(blue)", "on_table(red)", "start:stack(blue,red)"]),
    ("Initially the tower is blue on the bottom, then orange, then white on top. Put all three cubes on the table.",
     ["on_table(blue)", "on_table(orange)", "on_table(white)", "start:stack(blue,orange,white)"]),
])
def test_starts_are_read_by_the_whole_front_end_before_or_after_the_goal(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Start: red on white on black. Goal: put the white cube on the table; leave the others as they are.",  # from under red
    "Start: red on blue. Goal: all three cubes on the table.",  # the start has two
    "Start: a tower of three cubes. Goal: all cubes on the table.",  # which cubes start where is not said
])
def test_starts_that_are_not_stacks_of_named_cubes_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text", [
    # from a hostile tester of this session's features: each had compiled with words dropped
    "Stack the red cube on the blue cube (success rate 80%, in reverse).",  # an order change inside a report
    "Stack the red cube on the blue cube (50 episodes, upside down).",
    "Reverse the task in which the robot stacks the red cube on the blue cube.",  # a frame that changes the task
    'Do not give the task "stack the red cube on the blue cube".',  # a negation outside the quote
    'give the task "stack the red cube on the blue cube" in reverse',
    "Put the cube nearest the robot on the blue cube.",  # a cube picked by where it is
    "Put the red cube on the cube near the robot.",
    "Build a tower with the red cube at the bottom and three more cubes on the blue cube.",
    "Start: the red cube is on the blue cube. Take the blue cube off the red cube and set it down next to it.",
    "Start: the red cube is on the blue cube. Take the red cube off the green cube and set it down next to it.",
    "Start: the red cube is on the blue cube, which is on the green cube. Take the red cube off the blue cube and set it "
    "down next to it; leave the other three as they are.",  # two others, not three
    "Start: red on blue on green. Unstack the tower. Put the red cube on the green cube.",  # blue's end unsaid
    "Start: red on blue, green on yellow. Unstack the tower.",  # which tower
])
def test_attacks_on_reports_quotes_robot_places_and_starts_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_the_rest_of_a_start_stack_left_as_it_is_keeps_the_cubes_under_the_one_moved():
    text = ("Start: the red cube is on the blue cube, which is on the green cube. Take the red cube off the blue cube and "
            "set it down next to it; leave the other two as they are.")
    assert sorted(meaning(parse(text))) == ["next_to(blue,red)", "stack(green,blue)", "start:stack(green,blue,red)"]


def test_three_piles_of_one_colour_take_any_split():
    assert sorted(meaning(parse("make three separate piles, each of two brown cubes"))) == ["pile(brown,brown)"] * 3


@pytest.mark.parametrize("text, expected", [
    ("make a line of blocks: purple on the far left, cyan on the far right, and two gray blocks in between",
     ["line[left_to_right](purple,gray,gray,cyan)"]),
    ("The goal is a row of five cubes with the black cube exactly in the middle and the others white.",
     ["line[left_to_right](white,white,black,white,white)"]),
    ("the leftmost cube in the row should be yellow, then green, then pink on the far right",
     ["line[left_to_right](yellow,green,pink)"]),
    # the third cube said beside the end cube said before it (no task had been found)
    ("Put the orange block at the right, the pink block left of it and the gray block at the far left, all in one row.",
     ["line[left_to_right](gray,pink,orange)"]),
    ("Put the red cube at the right end of a row, the yellow cube to its left, and the green cube at the left end.",
     ["line[left_to_right](green,yellow,red)"]),
    # a cube named by no colour takes one its clause gives no other cube (it had been a second red cube)
    ("Put a block between the red block and the green block.", ["between(blue;green,red)"]),
])
def test_a_row_said_by_its_ends_and_middle_and_an_unnamed_cube_beside_named_ones(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "make a row of five blocks: purple on the far left, cyan on the far right, and two gray blocks in between",  # 4 said
    "the leftmost cube in the row should be yellow, then green, then pink on the far left",  # pink at both ends
    "a row of four cubes with the black cube in the middle and the others white",  # an even row has no middle cube
    "Put the red cube at the left end of a row, the yellow cube to its left, and the green cube at the right end.",  # no place
])
def test_a_row_whose_roles_do_not_add_up_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Build a tower of three: blue at the bottom, red at the top, and a green one between them.", ["stack(blue,green,red)"]),
    ("the topmost block of the tower should be green and the bottom one should be cyan, three blocks total",
     ["stack(cyan,red,green)"]),  # the goal's tower described (the middle cube is the only one left: no colour said)
    ("line up 4 cubes in the back row of the table, left to right: pink, pink, cyan, cyan",
     ["line[left_to_right](pink,pink,cyan,cyan)@back"]),
    # the paper's restack: the cube placed on top starts under the one it goes on (that one comes down first)
    ("Stack the red block on top of the yellow block; yellow starts stacked on red", ["stack(yellow,red)", "start:stack(red,yellow)"]),
])
def test_a_tower_described_by_its_roles_and_a_row_at_the_table_s_back_are_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_start_after_the_goal_whose_top_cube_goes_under_keeps_a_whole_stack_goal():
    from rpg.domain.predicates import Stack

    goal = parse("Put the red cube on the yellow cube. The yellow cube starts on top of the red cube.").goal_predicate()
    assert type(goal) is Stack and goal.objects == ("yellow", "red")  # not On(red, yellow): red's chain ends at the table


@pytest.mark.parametrize("text, expected", [
    ("For the pilot set, line up the green, purple and orange cubes.", ["line(green,orange,purple)"]),
    ("Okay sweetie, the robot's job is to put the green block on top of the yellow block.", ["stack(yellow,green)"]),
    ("The task consists in to place the yellow block at the right of the black block.", ["right_of(yellow,black)"]),
    ("In this experiment, the robot was instructed to place the green cube to the right of the blue cube.",
     ["right_of(green,blue)"]),
    ("stack four blue cubes into one tower and put a white cube in the front left corner.",  # white had joined the tower
     ["in_region(white,front_left)", "stack(blue,blue,blue,blue)"]),
])
def test_words_that_frame_a_task_for_a_person_are_dropped(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Use the ruler to line up the three black cubes.",  # a tool the domain lacks
    "Using a spatula, put the red cube on the blue cube",
    "Okay so, stack those on the blue cube.",  # 'those': cubes nobody named
    "Like the demo task, put the red cube on the blue cube.",  # what the words point at
])
def test_opening_words_that_may_change_the_task_are_not_dropped(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Left to right: red, green, blue.", ["line[left_to_right](red,green,blue)"]),  # an order alone is a row
    ("Place the cubes from front to back: cyan, brown, purple.", ["line[front_to_back](cyan,brown,purple)"]),
    ("Leftmost: gray. Rightmost: orange. Middle: white.", ["line[left_to_right](gray,white,orange)"]),
    ("Put any block on top of the red one.", ["stack(red,blue)"]),  # one more cube, whichever
    ("put one blue cube in each of the two back corners", ["in_region(blue,back_left)", "in_region(blue,back_right)"]),
])
def test_a_row_said_by_its_order_or_places_alone_and_corners_said_two_at_a_time(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Left to right: red, green, blue, in a tower",  # the order is no tower's
    "leftmost: orange, leftmost: gray, rightmost: pink",  # a place said twice
])
def test_an_order_said_of_something_else_is_not_made_a_row(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text", [
    # from a second hostile tester of this session's features
    "Okay sweetie, the robot's former job was to put the red block on the blue block.",  # not the job now
    "The task consists in part in to place the red cube on the green cube.",  # only a part of the task
    "In this experiment, the robot was wrongly instructed to place the yellow cube on the red cube.",
    "In this experiment, the human was instructed to place the yellow cube on the red cube.",  # not the robot's task
    "For the pilot set of three runs, line up the red, blue and green cubes from left to right.",  # a count in the frame
    "a line of blocks: purple on the far left, cyan on the far right, and gray blocks in between",  # how many?
    "the leftmost cube in the row should be yellow, then green, then pink on the far right of the table",  # whose place?
])
def test_second_attack_on_frames_and_rows_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_cubes_between_a_row_s_ends_whose_colour_is_not_said_take_any_cubes():
    m = meaning(parse("a line of blocks: purple on the far left, cyan on the far right, and two blocks in between"))
    assert m == ["line[left_to_right](purple,red,red,cyan)"]  # one colour: any two cubes may stand there


@pytest.mark.parametrize("text, expected", [
    ("Stack three cubes; the colours do not matter but the top one must be white.", ["stack(red,blue,white)"]),
    ("Make two towers: one of three green cubes on the left, one of three red cubes on the right.",
     ["stack(green,green,green)@left", "stack(red,red,red)@right"]),
    ("Make two rows: one of three red cubes, one of three blue cubes.", ["line(blue,blue,blue)", "line(red,red,red)"]),
])
def test_freedom_with_a_but_and_two_structures_said_after_a_colon_are_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_uncoloured_cubes_in_each_of_two_corners_are_not_given_one_corner_each():
    # it had demanded a red cube back left and a blue one front left, a goal stricter than the words (then refused):
    # unnamed cubes take one colour, so either may stand in either corner
    assert sorted(meaning(parse("put a cube in each of the two left corners"))) == [
        "in_region(red,back_left)", "in_region(red,front_left)"]


@pytest.mark.parametrize("text, expected", [
    # twenty-third session, read from stranger32 (the twenty-second session's transfer measure)
    ("Row of cubes along the back edge of the table: cyan, cyan, purple, in any order.", ["line(cyan,cyan,purple)@back"]),
    ("Make a row of two cyan cubes and a purple cube, in any order.", ["line(cyan,cyan,purple)"]),
    ("Goal: wall. Lower layer: white, gray, white. Upper layer: black, black, black.",
     ["wall(gray,white,white|black,black,black)"]),
])
def test_a_list_freed_by_in_any_order_and_layers_said_as_lower_and_upper(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_row_listing_a_colour_twice_keeps_its_order_unless_freed():
    assert meaning(parse("Make a row of cyan, purple, cyan cubes.")) == ["line[sequence](cyan,purple,cyan)"]


def test_cubes_that_should_end_up_stacked_are_stacked_in_any_order():
    goal = parse("the black, brown and pink cubes should end up stacked in one column").goal_predicate()
    assert type(goal).__name__ == "UnorderedStack"
    assert type(parse("the black cube should end up on the pink cube").goal_predicate()).__name__ == "Stack"


def test_a_pyramid_s_peak_cites_the_word_peak():
    from rpg.schema.citations import uncited
    schema = parse("stack a three-block pyramid using the pink, cyan and gray cubes with pink at the peak")
    assert meaning(schema) == ["pyramid(cyan,gray|pink)"] and uncited(schema) == []


@pytest.mark.parametrize("text", ["stack the green triangle on top of the white cube", "put a red wedge next to the blue cube"])
def test_a_coloured_triangle_or_wedge_is_a_piece_the_domain_lacks(text):
    with pytest.raises(Inexpressible, match="shape the domain does not have"):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("The white cube shall stand left from the black cube.", ["left_of(white,black)"]),
    ("Put gray cube on the right side from the white cube.", ["right_of(gray,white)"]),
    ("The red one must go in front to the blue one.", ["in_front_of(red,blue)"]),
    ("Place green cube to left from yellow cube, orange cube - to right from yellow.",
     ["left_of(green,yellow)", "right_of(orange,yellow)"]),
])
def test_a_learner_s_side_from_a_cube_is_its_side(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_tower_s_count_with_only_its_ends_said_as_headings_leaves_the_middle_free():
    goal = parse("Tower of 4. Base: gray. Top: yellow.").goal_predicate()
    assert type(goal).__name__ == "AnchoredStack" and len(goal.objects) == 4
    assert meaning(parse("Tower. Base: gray. Top: yellow.")) == ["stack(gray,yellow)"]
    assert meaning(parse("I want a tower of three where the middle block is yellow")) == ["stack(red,yellow,blue)"]


@pytest.mark.parametrize("text", [
    "Line up the digits 1, 2, 3 in ascending order from left to right, with 3 as the leftmost.",
    "line up the letters A, B, C from left to right with C on the far left",
    "line up red, green, blue from left to right with blue on the far left",
])
def test_an_end_given_to_another_cube_than_the_order_s_contradicts_it(text):
    with pytest.raises(ParseError, match="contradicts itself"):
        parse(text)


def test_an_end_given_to_the_order_s_own_end_cube_is_read():
    assert meaning(parse("Line up the digits 1, 2, 3 in ascending order from left to right, with 1 as the leftmost.")) == [
        "line[left_to_right](1,2,3)"]


@pytest.mark.parametrize("text", ["tiny blue on top of the big green", "put the small red one on the blue"])
def test_a_size_said_of_a_bare_colour_is_refused(text):
    with pytest.raises(Inexpressible, match="size"):
        parse(text)


def test_a_relation_restated_as_its_converse_is_one_constraint():
    schema = parse("Place the green cube left of the yellow cube, so the yellow cube is to the right of the green cube.")
    assert schema.goal_predicate().name == "left_of" and meaning(schema) == ["left_of(green,yellow)"]
    with pytest.raises(ParseError, match="contradict"):
        parse("put red behind blue and red in front of blue")


@pytest.mark.parametrize("text, expected", [
    ("make two separate piles: one with the brown and pink blocks, one with the white and cyan blocks",
     ["pile(brown,pink)", "pile(cyan,white)"]),
    ("Three towers, each two cubes tall: red on blue, green on yellow, white on black.",
     ["stack(black,white)", "stack(blue,red)", "stack(yellow,green)"]),
    ("I want two stacks: white on black, and black on white", ["stack(black,white)", "stack(white,black)"]),
    ("Place one red cube and one blue cube in the front half, next to each other.",
     ["in_region(blue,front)", "in_region(red,front)", "next_to(blue,red)"]),
    ("put the red cube and the blue cube side by side on the left side of the table",
     ["in_region(blue,left)", "in_region(red,left)", "next_to(blue,red)"]),
])
def test_structures_listed_after_a_colon_and_a_pair_s_place(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", ["Three towers, each three cubes tall: red on blue, green on yellow, white on black.",
                                  "Two towers: red on blue, green on yellow, white on black."])
def test_towers_listed_that_do_not_add_up_are_not_rewritten(text):
    with pytest.raises(ParseError):
        parse(text)


def test_a_grid_whose_rows_are_given_colours_is_refused_not_weakened():
    with pytest.raises(ParseError, match="row of the grid"):  # the grid goal would accept any cube at any site
        parse("make a 2x2 grid: top row two green blocks, bottom row two orange blocks")
    assert meaning(parse("Lay out six yellow cubes in a 2 by 3 grid: two rows of three.")) == [
        "grid(2x3:yellow,yellow,yellow,yellow,yellow,yellow)"]


@pytest.mark.parametrize("text, expected", [
    ("i want a line of blocks with black on the far left, pink on the far right, and gray between them",
     ["line[left_to_right](black,gray,pink)"]),
    ("the black cube goes in the middle of a row of three, with a white block on each side of it",
     ["line[left_to_right](white,black,white)"]),
    ("a row of three with the black cube in the middle and a white block on each side", ["line[left_to_right](white,black,white)"]),
    ("Make a row of cubes: first the orange, after the purple, last the pink, from the left.",
     ["line[left_to_right](orange,purple,pink)"]),
    ("the leftmost block in the row should be red, then blue, then the rightmost is green", ["line[left_to_right](red,blue,green)"]),
])
def test_a_row_said_by_its_ends_middle_and_steps(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text, expected", [
    ("stack the green and white blocks, doesnt matter which is on top", ["stack(green,white)"]),
    ("stack the green and white blocks, I don't mind which one goes on top", ["stack(green,white)"]),
    ("For this episode the purple block has to finish on top of the white block.", ["stack(white,purple)"]),
    ("My goal: move the gray block to the front of the table and leave it there.", ["in_region(gray,front)"]),
    ("The blue block belongs on the yellow patch.", ["on_patch(blue,patch:yellow)"]),
    ("Goal: the letter blocks spell out RED from left to right",
     ["line[left_to_right](R,E,D)", "reads(R,E,D;direction=left_to_right,face=up,text=RED)"]),
    ("I reckon the task is a tower: brown on the bottom, then orange, then yellow up top.", ["stack(brown,orange,yellow)"]),
    ("Great question! What you want is a pyramid: two pink cubes on the bottom and one white cube on top.",
     ["pyramid(pink,pink|white)"]),
    ("Thanks for your patience. The task you are describing is three cubes, red, white and blue, in a line from left to "
     "right. Happy to help further.", ["line[left_to_right](red,white,blue)"]),
])
def test_freedom_end_states_and_replies_around_a_task_are_read(text, expected):
    assert meaning(parse(text)) == expected
    if "doesnt" in text or "mind" in text:
        assert type(parse(text).goal_predicate()).__name__ == "UnorderedStack"


def test_a_colour_word_spelled_is_a_word_but_a_cube_of_that_colour_still_needs_a_place():
    with pytest.raises(ParseError, match="red cube"):
        parse("spell RED with the letter blocks from left to right and put the red cube behind them")


@pytest.mark.parametrize("text, expected", [
    ("move blue blok to rigth side of table", ["in_region(blue,right)"]),
    ("Keep the green cube besides the white cube.", ["next_to(green,white)"]),
    ("Please keep the cyan cube in front side of the purple cube.", ["in_front_of(cyan,purple)"]),
])
def test_misspellings_and_a_learner_s_prepositions(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text, expected", [
    # a start said as where the goal starts from: it had been read as part of the goal (silently wrong)
    ("from the tower of pink on cyan, put pink next to the white block", ["next_to(pink,white)", "start:stack(cyan,pink)"]),
    ("starting from a stack of red on blue, put the red cube on the table", ["on_table(red)", "start:stack(blue,red)"]),
    ("with the red cube stacked on the blue cube, move the red cube next to the green cube",
     ["next_to(green,red)", "start:stack(blue,red)"]),
    ("starting with the red-on-blue tower, put the red cube on the green patch", ["on_patch(red,patch:green)", "start:stack(blue,red)"]),
    # the start's one stack's ends named by the goal, a cube taken off and set nowhere else
    ("Initially red is on blue. Take the top cube off and put it on the table.", ["on_table(red)", "start:stack(blue,red)"]),
    ("The tower is red on blue. Take the top one off and put it on the table.", ["on_table(red)", "start:stack(blue,red)"]),
    ("Initially red is on blue. Take the red cube off.", ["on_table(red)", "start:stack(blue,red)"]),
    ("There's a stack of pink on cyan on gray. Remove just the top cube and leave the rest as is.",
     ["on_table(pink)", "stack(gray,cyan)", "start:stack(gray,cyan,pink)"]),
    ("Unstack the red-on-blue tower and put both cubes on the green patch.", ["on_patch(blue,red,patch:green)", "start:stack(blue,red)"]),
])
def test_a_start_said_as_where_the_goal_starts_from_and_its_ends_named(text, expected):
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    from rpg.schema.citations import uncited
    assert uncited(schema) == []


@pytest.mark.parametrize("text", ["put red on blue and leave the rest as is.", "move the rest to the left",
                                  "with the red cube on the blue cube, put the green cube on the red cube"])
def test_the_rest_without_a_start_and_a_with_clause_that_is_no_start(text):
    if text.startswith("with"):  # no participle of a state: read as the goal's own words, the tower of three
        assert meaning(parse(text)) == ["stack(blue,red,green)"]
    else:
        with pytest.raises(ParseError):
            parse(text)


def test_unnamed_cubes_take_one_colour_so_either_may_stand_in_either_place():
    assert sorted(meaning(parse("put a cube in the back left corner and a cube in the front left corner"))) == [
        "in_region(red,back_left)", "in_region(red,front_left)"]


@pytest.mark.parametrize("text, expected", [
    ("two blue and one orange in a row, orange in the centre", ["between(orange;blue,blue)", "line(blue,blue,orange)"]),
    ("LINE front edge: red, red, red", ["line(red,red,red)@front"]),  # a list before the place: the line's place
    ("put the red cube in the front half, left of the blue cube", ["in_region(red,front)", "left_of(red,blue)"]),
    ("put the red cube in the front half and make sure it is left of the blue cube", ["in_region(red,front)", "left_of(red,blue)"]),
    ("the task is done when the pink cube is on the red patch", ["on_patch(pink,patch:red)"]),
    ("get the black cube into the right half", ["in_region(black,right)"]),
    ("make a 3-block tower using pink blocks", ["stack(pink,pink,pink)"]),
    ("one cube per corner: blue back left, red back right, green front left, yellow front right",
     ["in_region(blue,back_left)", "in_region(green,front_left)", "in_region(red,back_right)", "in_region(yellow,front_right)"]),
    ("stack the cubes so the colours run gray, red, blue going downward", ["stack(blue,red,gray)"]),
    ("put the blue cube left of the tower of two pink cubes", ["left_of(blue,pink)", "stack(pink,pink)"]),
])
def test_roles_halves_completions_and_landmark_structures(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, reason", [
    ("line up minus two gray cubes", "quantity"),
    ("put zero cubes on the blue patch", "quantity"),
    ("stack the red cube on itself", "itself"),
    ("arrange the cubes into prisms", "shape"),
    ("put that one over there on the blue patch", "current scene"),
])
def test_must_refuse_texts_name_their_real_reason(text, reason):
    with pytest.raises(Inexpressible, match=reason):
        parse(text)


def test_more_cubes_than_a_task_holds_is_refused_as_a_quantity():
    with pytest.raises(BadInput, match="quantity"):
        check_feasibility(parse("build a tower of 300 red blocks"))


@pytest.mark.parametrize("text, expected", [
    ("arr matey, hoist the white cube onto the gray patch, aye", ["on_patch(white,patch:gray)"]),
    ("Listen up, recruit: black cube on the left side of the table!", ["in_region(black,left)"]),
    ("Hey team, put the red cube on the blue cube.", ["stack(blue,red)"]),
    ("put the red cube on the blue cube, savvy?", ["stack(blue,red)"]),
    ("Put the three orange blocks together in one pile in the middle, okay?", ["pile(orange,orange,orange)@center"]),
    ("Tower bottom to top: red, blue, yellow, A.", ["stack(red,blue,yellow,A)"]),  # a label after a comma is no call
])
def test_a_call_to_a_listener_at_a_sentence_s_edge_is_dropped(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", ["put the red cube on the blue cube, not", "How many blocks can you stack, sweetie?",
                                  "Thanks, that's all for today."])
def test_a_chunk_that_may_change_the_task_or_a_question_is_not_dropped(text):
    with pytest.raises(ParseError):
        parse(text)


def test_unnamed_cubes_told_apart_by_g_take_one_colour_and_others_keep_theirs():
    corners = parse("put a cube in the back left corner and a cube in the front left corner")
    assert len({a.color for a in corners.assets}) == 1  # either cube may stand in either corner
    for text in ("Stack two blocks on top of each other.", "Place both blocks onto the goal patch", "Place the blocks side by side",
                 "The robot must place each object into its corresponding patch.", "Align the blocks in a color gradient from left to right"):
        schema = parse(text)  # swapping them changes nothing G asks, or their colours are what G asks: kept as read
        cubes = [a for a in schema.assets if a.kind == "colored_cube"]
        assert len({a.color for a in cubes}) == len(cubes), text


@pytest.mark.parametrize("text, expected", [
    ("make a pyramid with three red cubes at the base, two blue above, and a white one topping it",
     ["pyramid(red,red,red|blue,blue|white)"]),  # the white cube had gone into the second layer, a blue one on top
    ("make a pyramid with three red cubes at the base, two blue above, and a white one crowning it",
     ["pyramid(red,red,red|blue,blue|white)"]),
    ("put the red cube in the back left corner and the cyan block in the front", ["in_region(cyan,front)", "in_region(red,back_left)"]),
])
def test_a_cube_topping_a_structure_and_a_second_cube_s_own_place(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    # from a hostile tester of this session's features: each had compiled silently wrong
    "put the red, blue and green cubes in a row, green in the centre, then put yellow on green",  # yellow joined the row
    "a row of red, blue, green, green in the centre",  # a second green made up
    "a row of five cubes, orange in the centre",  # every cube orange, the middle dropped
    "red, blue and green in a row left to right, green in the centre",  # a contradiction
    "two blue and one orange in a row, blue in the centre",  # the middle dropped
    "put a cube in each of the two left corners and put them next to each other",  # a third cube made up
    "one cube per corner: blue back left, red back left, green front left, yellow front right",  # two in one corner
    "the task is done when the red cube is on the blue cube, which starts on the green cube",  # the start read as goal
    "Did you put the red cube on the blue cube, savvy?",  # a question about what was done
    "Hey team, did you put the red cube on the blue cube?",
])
def test_attack_on_the_twenty_third_session_s_features_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_cubes_said_to_differ_in_colour_keep_their_colours_and_steps_keep_their_order():
    schema = parse("put a cube in the back left corner and a cube in the front left corner, different colours")
    assert len({a.color for a in schema.assets}) == 2
    assert meaning(parse("put in a row: first the orange, after the purple, last the pink")) == ["line[sequence](orange,purple,pink)"]
    assert meaning(parse("Make a line, from left to right, that starts with the black cube and ends with the white cube, "
                         "with the gray cube in the middle.")) == ["line[left_to_right](black,gray,white)"]


def test_two_cubes_placed_then_related_together_are_refused_not_half_read():
    with pytest.raises(ParseError, match="beyond the builtin parser"):  # red had lost 'left of the blue cube'
        parse("put the red and green cubes in the front half, left of the blue cube")


@pytest.mark.parametrize("text, expected", [
    # twenty-fourth session, from stranger34 and stranger33 (each had compiled silently wrong)
    ("make a red-on-yellow tower on the left side of the table", ["stack(yellow,red)@left"]),  # read as a list, red under
    ("a green-on-blue-on-red stack", ["stack(red,blue,green)"]),
    ("Make a tower where the purple cube is on top of the orange cube.", ["stack(orange,purple)"]),  # 'on top' read as an end
    ("the white cube should be at the top of a three block tower whose bottom cube is gray", ["stack(gray,red,white)"]),
    ("starting from yellow on cyan on red (red at the bottom), put the yellow and the cyan blocks down on the table",
     ["on_table(cyan)", "on_table(yellow)", "start:stack(red,cyan,yellow)"]),
    ("unstack everything: the tower is pink on top of yellow on top of green, and all of them should end up on the table",
     ["on_table(green)", "on_table(pink)", "on_table(yellow)", "start:stack(green,yellow,pink)"]),
    ("Unstack the tower: it is red on blue.", ["on_table(blue)", "on_table(red)", "start:stack(blue,red)"]),
])
def test_hyphened_towers_a_cube_s_end_said_first_and_starts_said_with_their_undoing(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, match", [
    ("starting from a stack of red on blue", "says where the cubes start"),  # no goal: the start had been the goal
    ("starting from red on blue", "says where the cubes start"),
    ("starting from a row of red and blue, put red on blue", "says where the cubes start"),  # a row starts nothing rpg builds
    ("starting from yellow on cyan on red (red at the top), put the yellow and the cyan blocks down on the table",
     "starting scene"),  # the parenthesis contradicts the chain
    ("unstack everything: the tower is pink on top of yellow, and put the green cube on the blue cube",
     "undoes the start's tower"),  # where pink and yellow end is not said
])
def test_a_start_that_cannot_be_read_is_refused_never_read_as_the_goal(text, match):
    with pytest.raises(ParseError, match=match):
        parse(text)


def test_a_listed_cube_that_starts_on_the_table_keeps_its_place_in_the_goal():
    schema = parse("Initially yellow is on cyan. Put yellow and cyan on the table")
    assert {p.a for p in schema.goal_predicate().walk() if type(p).__name__ == "OnTable"} == {"yellow", "cyan"}


@pytest.mark.parametrize("text, expected", [
    # what success requires, and when the goal holds, said around it (their words had been unknown)
    ("Success requires both white cubes to be on the black patch.", ["on_patch(white,white,patch:black)"]),
    ("Task T3 requires arranging digit cubes 1-3 in ascending order from left to right", ["line[left_to_right](1,2,3)"]),
    ("The yellow cube is placed behind the green patch in the final state.", ["behind(yellow,patch:green)"]),
    ("build a wall of eight grey blocks, four along and two high", ["wall(gray,gray,gray,gray,gray,gray,gray,gray)"]),
    # a row with one end named, a row said by its middle and its sides, a tower's one middle cube counted
    ("arange four blocks in a row, the leftmost one cyan", ["line[left_to_right](cyan,red,red,red)"]),
    ("put 4 cubes in a line; the rightmost one must be red", ["line[left_to_right](blue,blue,blue,red)"]),
    ("a row of three with the blue cube in the middle, red on its left and green on its right", ["line[left_to_right](red,blue,green)"]),
    ("tower: brown bottom, pink top, one gray block between them", ["stack(brown,gray,pink)"]),
])
def test_requirements_final_states_row_ends_and_a_counted_middle(text, expected):
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    from rpg.schema.citations import uncited
    assert uncited(schema) == []


@pytest.mark.parametrize("text", [
    "Success requires that red is not on blue",  # the negation is still read
    "the red cube is on blue in the final state of the previous run",  # a reference is still read
    "a wall of 6 cubes, 3 across and 3 high",  # 9 cubes, not 6
    "a row of three with the blue cube in the middle, red on its left and green on its left",
])
def test_requirements_and_row_roles_that_contradict_or_refer_are_still_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_a_row_s_unnamed_cubes_share_one_colour_so_any_may_stand_anywhere():
    schema = parse("a row of four blocks with a cyan block on the far left")
    assert sorted(a.color for a in schema.assets) == ["cyan", "red", "red", "red"]


@pytest.mark.parametrize("text, expected", [
    ("put a cube in each of the four corners",  # unnamed: four cubes of one colour, any in any corner
     ["in_region(red,back_left)", "in_region(red,back_right)", "in_region(red,front_left)", "in_region(red,front_right)"]),
    ("the stack should be three blocks tall with a purple block somewhere in it", ["stack(purple,red,red)"]),
    ("the blocks start stacked green, yellow, pink from bottom to top. unstack them all so every block is on the table",
     ["on_table(green)", "on_table(pink)", "on_table(yellow)", "start:stack(green,yellow,pink)"]),
    ("from a stack of brown, gray, red (bottom to top), remove the top two blocks and set them on the table",
     ["on_table(gray)", "on_table(red)", "start:stack(brown,gray,red)"]),
    ("initially the white cube is on the black cube. swap them so the black one ends on top",
     ["stack(white,black)", "start:stack(black,white)"]),
    ("the letter cubes should spell HAT along the back edge, left to right",
     ["line[left_to_right](H,A,T)@back", "reads(H,A,T;direction=left_to_right,face=up,text=HAT)"]),
    ("the bottom of the tower is green and the top is blue, with nothing in between", ["stack(green,blue)"]),
    # (the start's tower topped, as after "Initially the red cube is on the blue cube.": the start had not been read as a
    # stack here, thirty-second session)
    ("given a red cube sitting on a blue cube, put a green cube on the red cube", ["stack(blue,red,green)", "start:stack(blue,red)"]),
])
def test_unnamed_corners_a_cube_somewhere_in_a_tower_and_more_starts(text, expected):
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    from rpg.schema.citations import uncited
    assert uncited(schema) == []


def test_a_tower_with_a_cube_somewhere_in_it_leaves_the_order_free():
    assert type(parse("a tower of four cubes, one of them purple").goal_predicate()).__name__ == "UnorderedStack"


@pytest.mark.parametrize("text", [
    "initially the white cube is on the black cube. swap them so the white one ends on top",  # contradicts the swap
    "Initially red is on blue and blue is on green. swap them",  # which two is not said
    "a tower of three with green at the bottom and blue on top, nothing in between",  # three, and nothing between two
    "put red next to blue with nothing in between",  # a negation still
    "from a stack of brown, gray, red (bottom to top), remove the top three blocks",  # the whole stack: no 'top' ones
])
def test_swaps_and_top_cubes_that_do_not_fit_the_start_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Task: build a tower with the letter cubes so that reading from the top down it says CUP",
     ["reads(C,U,P;direction=top_to_bottom,face=front,text=CUP)", "stack(P,U,C)"]),
    ("digits 9, 4, 7: put them in a row, biggest on the left", ["line[left_to_right](9,7,4)"]),  # the heading is the cubes
    ("place a cube in the front left corner and another one in the back right corner",
     ["in_region(red,back_right)", "in_region(red,front_left)"]),  # one cube had been put in both corners
    ("put a red cube on the blue patch and another one on the green patch", ["on_patch(red,patch:blue)", "on_patch(red,patch:green)"]),
    ("a tower of green on red, and next to the tower a single yellow block", ["next_to(red,yellow)", "stack(red,green)"]),
    ("unstack the three-block tower (red, white, black from the bottom up) so all three blocks are on the table",
     ["on_table(black)", "on_table(red)", "on_table(white)", "start:stack(red,white,black)"]),
    ("take the top cube off the stack of white, gray, brown (white at the bottom) and put it on the table",
     ["on_table(brown)", "start:stack(white,gray,brown)"]),
])
def test_says_a_heading_of_cubes_another_one_a_fronted_place_and_starts_listed_in_the_goal(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "unstack the two-block tower (red, white, black from the bottom up) so all the blocks are on the table",  # 2 is not 3
    "take the top cube off the stack of white, gray, brown and put it on the table",  # which end is the top: not said
    "take the top cube off the stack of white, gray, brown (gray at the bottom) and put it on the table",  # gray is no end
])
def test_a_start_listed_in_the_goal_that_miscounts_or_leaves_its_top_unsaid_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # from a hostile tester of this session's features (each had compiled silently wrong, or crashed)
    ("start from red on blue, put red on the table", ["on_table(red)", "start:stack(blue,red)"]),
    ("starting out with red on blue, put red on the table", ["on_table(red)", "start:stack(blue,red)"]),
    ("starting from: yellow on cyan on red. put the yellow and the cyan blocks down on the table",
     ["on_table(cyan)", "on_table(yellow)", "start:stack(red,cyan,yellow)"]),
    ("starting from red on blue, put green on red, then put red on the table",  # the table had been dropped
     ["on_table(red)", "stack(red,green)", "start:stack(blue,red)"]),
    ("the blocks start stacked A, B, C from bottom to top. unstack them all",  # a ValidationError traceback
     ["on_table(A)", "on_table(B)", "on_table(C)", "start:stack(A,B,C)"]),
    ("make two red-on-yellow towers", ["stack(yellow,red)", "stack(yellow,red)"]),  # red had been at the bottom
    ("make two towers of red on yellow on blue", ["stack(blue,yellow,red)", "stack(blue,yellow,red)"]),
    ("make a red - on - yellow tower", ["stack(yellow,red)"]),
    ("make a red-on-yelow tower", ["stack(yellow,red)"]),  # a typo had kept the list order
    ("make a 1-on-2 tower", ["stack(2,1)"]),  # the labels had been dropped
    ("a row of four cubes, one of them purple", ["line(purple,red,red,red)"]),  # every cube had been purple
    ("the bottom of the tower is green and the top is blue, with one cube in between", ["stack(green,red,blue)"]),
    ("the task is arranging red, green, blue in a row, then stacking them", None),  # steps: refused, not the row alone
    ("put the pink cube on the orange patch then put the cyan cube behind the pink cube and then make a two cube tower "
     "of brown on gray", ["behind(cyan,pink)", "on_patch(pink,patch:orange)", "stack(gray,brown)"]),  # gray had gone there
])
def test_attack_on_the_twenty_fourth_session_s_starts_and_towers(text, expected):
    if expected is None:
        with pytest.raises(ParseError):
            parse(text)
    else:
        assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "red on blue. put red on the table",  # red on blue and on the table (it had compiled to red on blue)
    "put red on blue and put red on the table",
    "the red cube is on the blue cube right now; put it on the table",  # 'right now' had been the right side
    "make a red-on-yellow tower and a yellow-on-red tower",  # two towers merged into one through a shared colour
    "make a red on yellow tower and a blue on red tower",
    "make a red-on-yellow tower and another red-on-yellow tower",
    "make a three-block red-on-yellow tower",  # the count had been dropped
    "make a 3-block tower of red on yellow",  # two red cubes had been made up
    "make a big-on-small tower",  # sizes
    "make two towers of red on yellow on blue and green",
    "two towers of four cubes, one of them purple",  # every cube had been purple
    "make a tower: the bottom block is green and the middle block is blue",  # a tower of two has no middle
    "build a wall 3 across and 2 high and a red-on-blue tower",  # the tower had been dropped, its colours in the wall
    "build a 2x2 grid of gray cubes and a red on blue tower",
    "unstack everything: the tower is pink on top of yellow, and put the green cube on the blue cube",
])
def test_attack_texts_that_contradict_or_leave_cubes_unsaid_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_a_cube_somewhere_in_a_tower_with_its_top_said_leaves_the_rest_free():
    goal = parse("the stack should be three blocks tall with a purple block somewhere in it and a green block on top").goal_predicate()
    assert type(goal).__name__ == "AnchoredStack" and goal.top and goal.objects[-1] == "green"


@pytest.mark.parametrize("text", [
    "stack green, yellow, pink from bottom to top, and put a blue block on the table",  # blue had joined the tower
    "the red cube is now on the blue cube; put it on the table",  # which cube, or a contradiction
    "unstack everything: the tower is pink, yellow, green, and all of them should end up on the table",  # order unsaid
    "build a blue-on-red tower after unstacking the green-on-yellow tower",  # 'unstacking' had been read as 'stacking'
    "make the tower taller",  # the comparison had been dropped
    "Initially red is on blue. Build a tower of red on blue.",  # the goal holds at the start
])
def test_undone_towers_tables_comparisons_and_goals_that_hold_at_the_start_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_an_undone_tower_listed_with_its_order_is_the_start_and_a_prefix_is_never_stripped_by_a_typo_fix():
    assert sorted(meaning(parse("unstack everything: the tower is pink, yellow, green from top to bottom, and all of them "
                                "should end up on the table"))) == ["on_table(green)", "on_table(pink)", "on_table(yellow)",
                                                                  "start:stack(green,yellow,pink)"]
    assert "unstack" in normalize("build a blue on red tower after unstacking the green on yellow tower")[0]
    assert meaning(parse("Put the yellow cube inbetween the red cube and the blue cube.")) == ["between(yellow;blue,red)"]


@pytest.mark.parametrize("text, expected", [
    ("a tower from top to bottom: red, blue, green, with red on top", ["stack(green,blue,red)"]),  # red had gone on the wrong end
    ("In the final picture all the cubes are stacked in a single tower, bottom cube red, top cube cyan, with a yellow cube "
     "in between.", ["stack(red,yellow,cyan)"]),
    ("a row of four cubes, two of them purple", ["line(purple,purple,red,red)"]),
    ("a row of three cubes, one of them purple, the others red", ["line(purple,red,red)"]),
    ("build a red on-yellow tower", ["stack(yellow,red)"]),
    ("build two towers of red onto yellow", ["stack(yellow,red)", "stack(yellow,red)"]),
    ("3 by 3 grid of blocks, all of them orange", ["grid(3x3:orange,orange,orange,orange,orange,orange,orange,orange,orange)"]),
])
def test_roles_with_an_order_some_of_them_and_one_sided_hyphens(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "stack red, blue, green from bottom to top with blue at the bottom",  # the role had reordered the list said
    "a tower from top to bottom: red, blue, green, with green on top",
    "line up red, blue, green from left to right with red in the middle",
    "a row of red, blue, green from left to right, green on the left",
    "line up 1, 2, 3 in ascending order with 1 in the middle",
    "Row left to right: red, blue, green, in any order",
    "Hey you in the front left corner, put red on blue",  # the listener's place had become the goal's
    "Reversed, stack red, green, blue",
    "put a cube on the red patch and a cube in the back left corner",  # two cubes merged into one
    "put a cube on the red patch and stack a block on it",  # a third cube made up
    "start with cube 1 on cube 2, put cube 1 on the table",  # the start had become the goal
    "start with two towers of red on blue, put both reds on the table",
    "start with red beside blue, put red on blue",
    "given red on blue, green on yellow, put red on green",  # the second fact had joined the goal
    "put red on blue and then on the table",  # the table had been dropped
    "red ends on the table and on blue",
    "a row of four cubes, one of them purple, from left to right",  # every cube had been purple
    "a row of four cubes, at least one of them purple",
    "a tower: the middle block is blue, the others red",  # the middle had been dropped
    "a tower of three: the middle block is blue, the others red",  # the others had kept other colours
    "make the red-on-blue tower taller",
    "right now red is on blue. put green next to red",  # the scene now had become part of the goal
    "red is currently on blue; put red next to blue",
])
def test_second_attack_on_the_twenty_fourth_session_s_features_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text", [
    "build a red-next-to-yellow tower",  # a chain word no rewrite reads (it had been a stack)
    "build two 1-on-2 towers",  # the labels had been dropped
    "a 9-on-10 tower",
    "build two red-on-yellow towers and one yellow tower",  # the third tower had been dropped
    "a tower of three: the middle block is red and yellow",
    "build a 0-block tower of red on yellow",
])
def test_chain_words_no_rewrite_reads_and_towers_around_a_chain_are_refused(text):
    with pytest.raises(ParseError):
        parse(text)


def test_a_role_said_before_the_tower_names_its_listed_cube():
    # a second red cube had been made for "red at the bottom"
    assert meaning(parse("starting with red at the bottom, build a tower of red, blue and green")) == ["stack(red,blue,green)"]
    with pytest.raises(ParseError):  # the order said puts red on top: a contradiction
        parse("starting with red at the bottom, build a tower of red, blue and green from top to bottom")


@pytest.mark.parametrize("text, expected", [
    # the twenty-fifth session's reading of stranger35 (each had been refused or read wrong)
    ("Build a pyramid with three blue cubes on the bottom, two red cubes in the middle and one red cube on top.",
     ["pyramid(blue,blue,blue|red,red|red)"]),  # a colour in two layers had been refused as a contradiction
    ("Four blocks, two orange and two purple, form a wall two high. The orange pair is on the bottom.",
     ["wall(orange,orange|purple,purple)"]),  # 'the orange pair' had read 'the orange 2': the layer dropped
    ("The blue cube starts on top of the green cube. Take it off and put it on the table.",
     ["on_table(blue)", "start:stack(green,blue)"]),
    ("The green block starts on the brown block. Put the gray block on top of it.",
     ["stack(brown,green,gray)", "start:stack(brown,green)"]),
    ("Initially green is on brown. Put gray on top.", ["stack(brown,green,gray)", "start:stack(brown,green)"]),
    ("Initially red is stacked on yellow. Swap them so yellow is on red.", ["stack(red,yellow)", "start:stack(yellow,red)"]),
    ("Make a horizontal row of the yellow, green and cyan cubes with yellow leftmost and cyan rightmost.",
     ["line[left_to_right](yellow,green,cyan)"]),
    ("The purple and yellow blocks should end up in a row along with the green block.", ["line(green,purple,yellow)"]),
    ("Place the cyan, purple and brown cubes in a row running from the front of the table to the back, in that order.",
     ["line[front_to_back](cyan,purple,brown)"]),
    ("Build a tower of three blocks with the black block on top and two yellow blocks below it.",
     ["stack(yellow,yellow,black)"]),
    ("Episode ends when the black cube is in the front left corner.", ["in_region(black,front_left)"]),
    ("End the episode when red is on blue.", ["stack(blue,red)"]),
])
def test_layers_shared_by_a_colour_starts_taken_off_or_topped_and_episode_ends(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, why", [
    ("Make a row of exactly three cubes using two purple cubes, two cyan cubes and one brown cube.", "row of exactly 3"),
    ("build a pyramid with the red cube at the bottom and the red cube on top", "two layers"),
    ("Move the white cube to the front right corner and keep it in the back left corner.", "contradict"),
    ("Build the same tower you built last time.", "earlier"),
    ("Make the same row we made yesterday.", "earlier"),
    ("Initially red is stacked on yellow. Swap them so yellow is on blue.", None),
])
def test_counts_exactly_said_one_cube_in_two_places_and_earlier_structures_are_refused(text, why):
    with pytest.raises(ParseError) as err:
        check_feasibility(parse(text))
    if why:
        assert why in str(err.value)


@pytest.mark.parametrize("text, expected", [
    ("The goal is a wall made of six cubes: a bottom course of orange cubes and a top course of purple cubes, three each.",
     ["wall(orange,orange,orange|purple,purple,purple)"]),  # 'course' (a wall's row of bricks) had been an unknown word
    ("Put red on blue and, of course, green on red.", ["stack(blue,red,green)"]),  # "of course" is no row
    ("Place the number cubes 5 and 8 in a row, 8 on the left.", ["line[left_to_right](8,5)"]),
    ("Place the number cubes 5 and 8 in a row, 5 on the left.", ["line[left_to_right](5,8)"]),
    ("Put the digit cubes 1, 2 and 3 in a row with 3 on the left and 1 on the right.", ["line[left_to_right](3,2,1)"]),
    ("Put the letters A and B in a row with B on the left.", ["line[left_to_right](B,A)"]),
])
def test_courses_of_a_wall_and_labelled_rows_whose_ends_are_said(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_a_labelled_row_with_one_end_said_twice_is_refused():
    with pytest.raises(ParseError):
        parse("Put the number cubes 5 and 8 in a row, 8 on the left, 5 on the left.")


@pytest.mark.parametrize("text, expected", [
    ("Form a circle of four purple cubes in the centre of the table.", ["circle(purple,purple,purple,purple)@center"]),
    ("Form a circle with four purple cubes around the centre of the table.", ["circle(purple,purple,purple,purple)@center"]),
    ("build a row of four black blocks in the middle of the table", ["line(black,black,black,black)@center"]),
])
def test_a_structure_wider_than_the_centre_stands_with_its_middle_there(text, expected):
    schema = check_feasibility(parse(text))
    assert meaning(schema) == expected
    centred = [p for p in schema.goal_predicate().walk() if p.name == "centred_in"]
    assert len(centred) == 1 and not [p for p in schema.goal_predicate().walk() if p.name == "in_region"]
    # the goal layout holds it: the cubes' middle in the centre third, some cube outside it
    (x0, x1), (y0, y1) = region_boxes("center")[0]
    xy = np.array([schema.goal_layout[n].position[:2] for n in centred[0].objects])
    assert x0 <= xy[:, 0].mean() <= x1 and y0 <= xy[:, 1].mean() <= y1
    assert any(not (x0 <= x <= x1 and y0 <= y <= y1) for x, y in xy)


def test_a_structure_that_fits_the_centre_keeps_every_cube_there():
    schema = parse("build a row of two black blocks in the middle of the table")
    assert {p.name for p in schema.goal_predicate().walk()} >= {"in_region"}
    assert not [p for p in schema.goal_predicate().walk() if p.name == "centred_in"]


@pytest.mark.parametrize("text, expected", [
    ("Make a column of three blue cubes running from front to back.", ["line[front_to_back](blue,blue,blue)"]),
    ("Line up 4 gray blocks running from the front of the table to the back.", ["line[front_to_back](gray,gray,gray,gray)"]),
    ("a row of three cubes (red, green, blue) running from front to back.", ["line[front_to_back](red,green,blue)"]),
])
def test_a_structure_running_from_one_side_to_the_other(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Build the tower from the example.", "Stack the cubes like in the example.", "Build a tower like in the demo.",
])
def test_a_structure_from_an_example_nobody_gave_is_refused_as_a_reference(text):
    with pytest.raises(Inexpressible, match="shown or seen"):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # cubes sent to places of their own, one group after another (each had found no task)
    ("put the two green blocks in the back and the two blue blocks in the front",
     ["in_region(blue,front)", "in_region(blue,front)", "in_region(green,back)", "in_region(green,back)"]),
    ("all the green blocks go in the back, all the blue blocks go in the front",
     ["in_region(blue,front)", "in_region(blue,front)", "in_region(green,back)", "in_region(green,back)"]),
    ("put every green block in the back and every blue block in the front", ["in_region(blue,front)", "in_region(green,back)"]),
    # the first part's verb carried to the second (the blue cubes had been read as cubes put on the right, not piled)
    ("Pile the red cubes on the left and the blue cubes on the right.", ["pile(blue,blue,blue)@right", "pile(red,red,red)@left"]),
])
def test_groups_of_cubes_each_sent_to_its_own_place(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "stack the red cubes on the left and the blue cubes on the right",  # a stack cannot stand in two sides
    "make a tower of two blue blocks on the right and put the red block on the left",
])
def test_parts_that_refer_to_each_other_or_contradict_are_not_split(text):
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


def test_a_part_that_refers_to_the_cube_placed_before_is_read_with_it():
    # 'it' refers across the parts: the cube of the part before (it had been refused, as parts not to split)
    assert sorted(meaning(check_feasibility(parse("put the red block on the left and the blue block on the right of it")))) \
        == ["in_region(red,left)", "right_of(blue,red)"]


@pytest.mark.parametrize("text, expected", [
    ("need a 3-block tower asap, green on top, two orange under it", ["stack(orange,orange,green)"]),
    ("Put the white cube at the bottom of a three-cube tower, with the two pink cubes above it.", ["stack(white,pink,pink)"]),
    ("put one cube in each corner of the table: red front left, blue front right, green back left, yellow back right",
     ["in_region(blue,front_right)", "in_region(green,back_left)", "in_region(red,front_left)", "in_region(yellow,back_right)"]),
    ("one cube is moved to each corner: red to back-left, blue to back-right, green to front-left and yellow to front-right.",
     ["in_region(blue,back_right)", "in_region(green,front_left)", "in_region(red,back_left)", "in_region(yellow,front_right)"]),
    ("Goal: yellow cube in the back, green cube in the front.", ["in_region(green,front)", "in_region(yellow,back)"]),
])
def test_roles_below_or_above_the_named_end_corners_listed_and_places_said_in_turn(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_each_corner_with_a_corner_left_out_is_refused():
    with pytest.raises(ParseError):
        parse("put one cube in each corner of the table: red front left, blue front right")


def test_two_towers_each_said_with_its_side_are_two_unordered_towers():
    # they had been read as one tower and a relation (then refused); each tower's order is not said
    schema = parse("build a tower of red and blue on the left and a tower of green and yellow on the right")
    assert sorted(meaning(schema)) == ["stack(green,yellow)@right", "stack(red,blue)@left"]
    assert [p.name for p in schema.goal_predicate().walk()].count("unordered_stack") == 2


@pytest.mark.parametrize("text, expected", [
    # from a hostile tester of this session's features
    ("Cluster the red cubes on the left and the blue cubes on the right.", ["pile(blue,blue,blue)@right", "pile(red,red,red)@left"]),
    ("line up the yellow, red and cyan cubes, yellow leftmost and cyan rightmost", ["line[left_to_right](yellow,red,cyan)"]),
    ("a wall of three rows: bottom red, middle green, top blue",  # every row had been given colours nobody said
     ["wall(red,red,red|green,green,green|blue,blue,blue)"]),
    ("build towers of 3 and 2 blocks", ["stack(red,red)", "stack(red,red,red)"]),  # both had been 3 high
    ("build two towers, of 3 and 2 blocks", ["stack(red,red)", "stack(red,red,red)"]),  # both had been 2 high
    ("Initially green is on brown. Put gray on top.", ["stack(brown,green,gray)", "start:stack(brown,green)"]),  # the tower kept, gray on its top
])
def test_attack_on_the_twenty_fifth_session_s_features(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Initially green is on brown. Put gray on top. Put white on top.",  # white had gone under gray
    "Initially green is on brown. Put gray on top. Put white on top of it.",
    "build a tower of the two green blocks in the back and the two blue blocks in the front",  # the blue ones a tower too?
    "a tower of red and blue, along with a green cube",  # green had joined the tower
    "a tower of four blocks: black on top, yellow under it",  # yellow had gone to the bottom
    "a tower of three blocks with the black block on top and yellow blocks below it",  # one yellow cube for 'blocks'
    "a pyramid of five cubes with three blue cubes on the bottom, two green cubes in the middle and one red cube on top",
    "a pyramid with three blue cubes on the bottom, two red cubes in the middle and one red cube on top, using only two "
    "red cubes",
    "a wall of four cubes. The orange pair is on the bottom. The orange pair is on top.",
    # a tower of cubes said to stand in two corners (the corners had been dropped from the meaning)
    "put the red cube in the back left corner and the yellow cube in the front right corner. put the red cube on the "
    "yellow cube.",
    "put one cube in each corner of the table: red front left, blue front right, green back left, yellow back right, "
    "blue on top of red",
    "put 5 and 8 in a row",  # four coloured cubes had been made
    "put 2 and 3 in a tower",
])
def test_attack_texts_on_the_twenty_fifth_session_s_features_are_refused(text):
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Build a tower: orange on the bottom, then green, then purple on top. Put the tower on the white patch.",
     ["on_patch(orange,patch:white)", "stack(orange,green,purple)"]),  # green had been dropped
    ("Put the red block far from the blue block. Put the green block between the two.",
     ["between(green;blue,red)", "far_from(blue,red)"]),
])
def test_a_tower_then_put_on_a_patch_and_a_cube_between_the_two_named_before(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_between_them_after_more_than_two_cubes_is_refused():
    with pytest.raises(ParseError):
        parse("put the red cube next to the blue cube and the yellow cube next to the green cube, then a white cube between them")


def test_a_line_said_by_its_ends_and_middle_in_a_direction_is_read_in_order():
    # black had been dropped (then the text was refused); the middle's colour is no further item of a list
    assert meaning(parse("a line from left to right starting with black and ending with white, grey in the middle")) == [
        "line[left_to_right](black,gray,white)"]


@pytest.mark.parametrize("text", [
    "a row of four cubes with red next to blue",  # the row alone had carried 'next to': the relation was dropped
    "a row of four cubes with red on blue",
    "a circle of four cubes with red opposite blue",
    "make a row of three cubes with the red cube next to the blue cube",
])
def test_a_relation_inside_a_structure_s_with_clause_that_the_goal_does_not_carry_is_refused(text):
    with pytest.raises(ParseError, match="relates two cubes"):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("a row of red, green and blue from left to right with red next to green", ["line[left_to_right](red,green,blue)"]),
    ("Black cube on top of the brown cube, with the brown cube sitting on the green patch.",
     ["on_patch(brown,patch:green)", "stack(brown,black)"]),
])
def test_a_relation_in_a_with_clause_that_the_goal_carries_is_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "a row of three cubes from left to right, red first",  # every cube had been red
    "a row of three cubes from left to right starting with red",
    "a tower of letter cubes with A on top",  # B, C and D had been made up under A
    "a tower of letters with A at the bottom",
])
def test_one_end_said_of_a_structure_whose_other_cubes_are_unsaid_is_refused(text):
    with pytest.raises(ParseError):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Put the letter cubes A and B next to each other.", ["next_to(A,B)"]),  # two coloured cubes had been made
    ("Place the number cubes 3 and 7 beside each other", ["next_to(3,7)"]),
    ("Put the letter cubes A and B next to each other with B to the left of A.", ["left_of(B,A)", "next_to(A,B)"]),
])
def test_labelled_cubes_next_to_each_other_and_a_second_relation_after_with(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_start_topped_twice_is_refused_even_when_the_second_says_on_top_of_a_cube():
    # (the guard against a second 'on top' had held a backspace for its word boundary, so it never matched; this text is
    # refused because 'gray on top' and white on gray contradict)
    with pytest.raises(ParseError):
        parse("Initially green is on brown. Put gray on top. Put white on top of the gray cube.")


@pytest.mark.parametrize("text, expected", [
    ("Place the number cubes 5 and 8 in a row, 8 on the left of 5.", ["line[left_to_right](8,5)"]),  # had been a sequence
    ("Place the number cubes 5 and 8 in a row, 8 right of 5.", ["line[left_to_right](5,8)"]),
    ("Put the digit cubes 1 and 2 in a row with 2 to the left of 1.", ["line[left_to_right](2,1)"]),
])
def test_a_labelled_row_of_two_ordered_by_one_side_of_the_other(text, expected):
    assert meaning(parse(text)) == expected


def test_one_label_beside_another_in_a_longer_row_is_refused():
    with pytest.raises(ParseError, match="orders two cubes"):
        parse("Place the number cubes 5, 8 and 3 in a row, 8 left of 5.")


def test_a_labelled_row_of_two_with_both_ends_said():
    # (found in review: the row had kept only the left end's cube, and the other was refused as having no place)
    assert meaning(parse("Place the number cubes 5 and 8 in a row, 8 on the left and 5 on the right.")) == [
        "line[left_to_right](8,5)"]


@pytest.mark.parametrize("text, expected", [
    # four stranger sets said a cube diagonally from another as two relations; both had been refused as contradicting
    ("Place the yellow block to the right of the white block and also in front of it.",
     ["in_front_of(yellow,white)", "right_of(yellow,white)"]),
    ("place the blue block behind the red one and also to its left", ["behind(blue,red)", "left_of(blue,red)"]),
    ("Put the red block left of the blue block and the blue block behind the red block.", ["behind(blue,red)", "left_of(red,blue)"]),
    # the twenty-fourth session's attack: in front had been dropped, then the two were refused as contradicting
    ("put the red cube in front to the left of the blue cube", ["in_front_of(red,blue)", "left_of(red,blue)"]),
])
def test_two_relations_of_one_pair_along_both_axes_read_diagonally(text, expected):
    spec = parse(text)
    assert sorted(meaning(spec)) == expected
    rels = [p for p in spec.goal.conjuncts() if p.name in ("left_of", "right_of", "in_front_of", "behind")]
    assert len(rels) == 2 and all(p.diagonal for p in rels)


@pytest.mark.parametrize("text", [
    "Put the red block left of the blue block and to the right of it.",  # one axis, both ways
    "put red left of blue and in front of blue and behind blue",  # a third relation against one of the two
])
def test_relations_one_pair_cannot_meet_are_still_refused(text):
    with pytest.raises(ParseError, match="contradict"):
        parse(text)


def test_one_relation_alone_still_keeps_the_cubes_level():
    (rel,) = [p for p in parse("Put the red block left of the blue block.").goal.conjuncts() if p.name == "left_of"]
    assert not rel.diagonal and "diagonal" not in rel.to_dict()  # the files of tasks written before it unchanged


def test_a_diagonal_pair_compiles_and_its_goal_state_meets_both(tmp_path):
    from rpg.compiler import compile_instruction

    result = compile_instruction("Place the yellow block to the right of the white block and also in front of it.",
                                 tmp_path, name="diag")
    assert result.valid, result.gates


@pytest.mark.parametrize("text, expected", [
    # a tower's count said after "with", "out of" or a comma, and its one colour after it (had found no task)
    ("Tall tower, six cubes, all of them red.", ["stack(red,red,red,red,red,red)"]),
    ("make a tower with 5 cubes all pink", ["stack(pink,pink,pink,pink,pink)"]),
    ("build a tower out of 4 cubes, all yellow", ["stack(yellow,yellow,yellow,yellow)"]),
    ("a tower with four cubes, every one of them blue", ["stack(blue,blue,blue,blue)"]),
    ("tower, 3 cubes, red", ["stack(red,red,red)"]),
])
def test_a_towers_count_after_with_or_a_comma_and_its_one_colour(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text, expected", [
    # a tower said cube by cube, each by an end or by the cube said before (had found no task, or lost a cube)
    ("Put a green cube down, a white cube on it, and another green cube on top of that.", ["stack(green,white,green)"]),
    ("Place red block as the base, green block above it, and blue block at the top.", ["stack(red,green,blue)"]),
    ("Leave the purple block on the table, put the orange one on it, then the red one ontop of that.",
     ["stack(purple,orange,red)"]),
    ("Your job is to build a tower of three: a purple block at the base and both pink blocks on it.", ["stack(purple,pink,pink)"]),
    # "it" here is the middle cube, the first said: the only reading that gives each cube one place
    ("Make a stack of three cubes with the red one in the middle, a blue one below it and a green one above it.",
     ["stack(blue,red,green)"]),
    # the tower's cubes listed, then roles by ends and by cubes named
    ("Puzzle: build a tower of the red, blue and yellow cubes so that red is directly above blue and yellow is at the "
     "very bottom.", ["stack(yellow,blue,red)"]),
    ("Build a tower of the blue, green and orange cubes on the white patch, blue at the bottom and orange at the top.",
     ["on_patch(blue,patch:white)", "stack(blue,green,orange)"]),
    ("Stack the cubes so that orange is on top, blue is under it, and green is at the very bottom.", ["stack(green,blue,orange)"]),
])
def test_a_tower_said_cube_by_cube(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "put the red block on the table, and the blue block beneath it",  # below a cube on the table: no tower
    "build a tower of 4 with red at the bottom, blue on it and green on top",  # four said, three placed
    "Put the red block down and the blue block on that, but not the green",
    "build a tower of the red, blue and yellow cubes so that red is above blue",  # three orders do
    "build a tower of the red, blue and green cubes, red on blue",  # green above or below them
])
def test_a_tower_said_cube_by_cube_that_places_no_cube_once_is_refused(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # layers listed from the bottom with "then", and a base of single cubes with one noun (had been misread and refused)
    ("Construct a pyramid, bottom layer blue blue blue, then red red, then yellow.", ["pyramid(blue,blue,blue|red,red|yellow)"]),
    ("A two-level pyramid: a base of a cyan and a brown block, with a white block on top.", ["pyramid(brown,cyan|white)"]),
    ("a wall, bottom row red, red, red, then blue, blue, blue", ["wall(red,red,red|blue,blue,blue)"]),
])
def test_layers_said_in_turn_from_the_bottom(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text, expected", [
    ("Stack the letter cubes so that the tower says HAT from top to bottom.",
     ["reads(H,A,T;direction=top_to_bottom,face=front,text=HAT)", "stack(T,A,H)"]),  # "says": what it reads
    ("Construct a wall whose bottom row is orange, purple, orange and whose top row is purple, orange, purple.",
     ["wall(orange,orange,purple|orange,purple,purple)"]),
    ("Sort the cubes into piles by colour: the two red ones in one pile and the two green ones in another.",
     ["piles(green,green,red,red;by=color)"]),  # one pile, and another: two
    ("Two towers please. One has green on red, the other has yellow on purple.", ["stack(purple,yellow)", "stack(red,green)"]),
])
def test_says_whose_one_pile_and_another_and_towers_said_after_them(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    # a pronoun before a colon's list stands for the cubes listed (had been refused as naming nothing)
    ("stack them in this order from the table up: cyan, white, cyan", ["stack(cyan,white,cyan)"]),
    ("put them in a row, left to right: red, blue, green", ["line[left_to_right](red,blue,green)"]),
    # a row's cubes listed after its colon are its order, either way along it
    ("line them up: yellow, blue, red", ["line[sequence](yellow,blue,red)"]),
    ("Row: yellow, blue, red", ["line[sequence](yellow,blue,red)"]),
])
def test_a_pronoun_before_a_colons_list_and_a_rows_list_after_its_colon(text, expected):
    assert meaning(parse(text)) == expected


def test_a_pronoun_before_a_colon_with_one_cube_still_refers_to_nothing():
    with pytest.raises(Inexpressible):
        parse("stack them: red")


@pytest.mark.parametrize("text, expected", [
    # "the other blue cube" set apart by the one blue cube said before it: a second blue cube (had been refused)
    ("line up the blue cube, the yellow cube and the other blue cube, from left to right.", ["line[left_to_right](blue,yellow,blue)"]),
    ("put the blue cube on the red patch and the other blue cube on the green patch",
     ["on_patch(blue,patch:green)", "on_patch(blue,patch:red)"]),
])
def test_the_other_cube_of_a_colour_said_before(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "put the other blue cube on the red patch",  # no blue cube said before: one the speaker sees
    "Initially the blue cube is on the red cube. Put the other blue cube on the green patch.",  # contrasted with the start's
])
def test_the_other_cube_of_a_colour_nobody_set_apart_is_still_refused(text):
    with pytest.raises(Inexpressible):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("make two towers one red on green the other white on black", ["stack(black,white)", "stack(green,red)"]),
    ("The image shows two separate towers. One is green on yellow. The other is blue on pink.", ["stack(pink,blue)", "stack(yellow,green)"]),
    # a start said as "there is a tower with ...", then the cube taken off
    ("There is a tower with the purple cube on top of the yellow cube. Take the purple one off and put it on the table.",
     ["on_table(purple)", "start:stack(yellow,purple)"]),
])
def test_two_towers_each_said_after_them_and_a_start_said_with_there_is(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    ("Place the blue cube at the corner behind, on the right of the table.", ["in_region(blue,back_right)"]),
    ("Put the cube brown in the corner of the front at the left.", ["in_region(brown,front_left)"]),
    ("two towers: (1) cyan on purple (2) white on black", ["stack(black,white)", "stack(purple,cyan)"]),
])
def test_a_corner_said_by_its_two_sides_apart_and_numbered_towers(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", ["put red in the corner at the back", "put red in a corner at the front"])
def test_a_corner_said_by_one_side_is_refused(text):
    # (it had been read as the back or front edge, the corner dropped)
    with pytest.raises(ParseError, match="names no one corner"):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Build a 4-block tower. Bottom: brown. Then orange, then yellow. Top: white.", ["stack(brown,orange,yellow,white)"]),
    ("Challenge: Tower of 3. Middle cube must be white. Others: any.", None),  # white in the middle, the ends free
    ("a tower of 4 cubes. The cube at the top is orange and the cube at the bottom is purple.", None),
])
def test_a_towers_roles_said_as_sentences_or_with_then_between_its_ends(text, expected):
    spec = parse(text)
    if expected is not None:
        assert meaning(spec) == expected
    elif "Middle" in text:
        assert [p.name for p in spec.goal.conjuncts()] == ["unordered_stack", "in_layers"]
    else:
        assert spec.goal.name == "anchored_stack" and spec.goal.bottom and spec.goal.top and len(spec.goal.objects) == 4


def test_a_list_of_cubes_said_without_its_commas():
    assert meaning(parse("ok so line up the blue cube the white cube and the black cube from left to right")) == [
        "line[left_to_right](blue,white,black)"]


@pytest.mark.parametrize("text, expected", [
    # silent errors a helper found in the session's unread set (its texts unseen; these examples are the helper's own):
    # a cube put on the start tower's top cube named: the tower, topped (the start's base had been dropped from G)
    ("Beginning with the orange block stacked on the brown block, set the white block on top of the orange block.",
     ["stack(brown,orange,white)", "start:stack(brown,orange)"]),
    ("Initially the orange block is on the brown block. Put the white block on the orange block.",
     ["stack(brown,orange,white)", "start:stack(brown,orange)"]),
    # a cube put on top, then the whole tower restated: counted once (it had been a fourth cube under the tower)
    ("Start: blue on white. Goal: put a brown cube on top, so the tower reads white, blue, brown from the bottom.",
     ["stack(white,blue,brown)", "start:stack(white,blue)"]),
    ("put a brown cube on top, so the tower is brown, blue, white from top to bottom", ["stack(white,blue,brown)"]),
    # a stack's base said on the table after a start: said by the stack (no separate on_table atom in the meaning)
    ("Start state: green cube on the table and a purple cube on top of it. Goal state: purple cube on the table and the "
     "green cube on top of it.", ["stack(purple,green)", "start:stack(green,purple)"]),
])
def test_what_the_unread_sets_silent_errors_were(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_cube_put_on_the_start_towers_bottom_cube_is_still_as_said():
    assert sorted(meaning(parse("Initially the orange block is on the brown block. Put the white block on the brown block."))) == [
        "stack(brown,white)", "start:stack(brown,orange)"]


@pytest.mark.parametrize("text, expected", [
    # the ordinary refusal classes a helper described in the unread set (these examples are the helper's own)
    ("Set the pink cube on the orange cube, and after that set the gray cube on top of that.", ["stack(orange,pink,gray)"]),
    ("Put the brown block on the table, stack the gray block on it, and finish by placing the orange block on the gray one.",
     ["stack(brown,gray,orange)"]),
    ("we want a row running left to right of black, orange, orange", ["line[left_to_right](black,orange,orange)"]),
    ("Put the two gray cubes in one pile and the two pink cubes in a separate pile.", ["piles(gray,gray,pink,pink;by=color)"]),
])
def test_steps_after_that_a_rows_direction_with_a_verb_and_a_separate_pile(text, expected):
    assert meaning(parse(text)) == expected


def test_piles_of_groups_nobody_counted_are_still_refused():
    with pytest.raises(BadInput):
        parse("put the red cubes in one pile and the blue cubes in another")


@pytest.mark.parametrize("text", [
    # a hostile helper's silent errors against this session's readings, each now refused
    "make a tower with 5 cubes, all pink but one",  # "but one" had been dropped: all pink
    "make a tower with 5 cubes all pink and one red",  # six cubes, red put on top by no word
    "build a pyramid with a base of a cyan, a brown and a pink block",  # pink had gone to the top
    "put the green cube down, a white cube on it, and the green cube on top of that",  # one cube in two places
    "stack the cubes so that orange is on top, blue is under it, and orange is at the very bottom",
    "stack them from the table up: cyan, white, red, and put the blue cube next to them",  # a red had been added
    "stack them in this order from the table up: cyan, white, red on the green patch",  # a blue cube had been made up
])
def test_the_sessions_readings_attacked_refuse(text):
    with pytest.raises(BadInput):
        parse(text)


def test_a_tower_says_a_list_of_letters_as_reads_does():
    # ("says" had been rewritten after the labels were read: H at the bottom, the reading dropped)
    assert sorted(meaning(parse("the tower says H, A, T"))) == sorted(meaning(parse("the tower reads H, A, T")))


@pytest.mark.parametrize("text, expected", [
    # twenty-seventh session, from stranger37's refusals (read as development material)
    ("Put the two yellow cubes in one pile and the two purple cubes in a seprate pile.", ["piles(purple,purple,yellow,yellow;by=color)"]),
    ("two by two grid using the red, blue, yellow and green cubes", ["grid(2x2:blue,green,red,yellow)"]),
    ("Pyramid with a bottom layer of cyan and brown and a top layer of green.", ["pyramid(brown,cyan|green)"]),
    ("Build a pyramid. Three blue cubes go on the bottom, two green cubes in the middle and one red cube on top.",
     ["pyramid(blue,blue,blue|green,green|red)"]),
    ("Corner task for the new policy. Place the white cube in the front left corner and the black cube in the back right "
     "corner.", ["in_region(black,back_right)", "in_region(white,front_left)"]),
    ("Build a pyramid of six red cubes. Take your time.", ["pyramid(red,red,red,red,red,red)"]),
    # cubes introduced in a sentence of their own, placed by a pronoun in the next
    ("There are two blue cubes on the table. Place both of them on the blue patch.", ["on_patch(blue,blue,patch:blue)"]),
    ("There is a red cube and a blue cube. Put them on the green patch.", ["on_patch(blue,red,patch:green)"]),
    ("Pick up the red cube. Put it on the green patch.", ["on_patch(red,patch:green)"]),
    ("Make a single tower out of the orange cube, the white cube and the black cube. I do not care which goes where.",
     ["stack(orange,white,black)"]),
    # a cube put down with no place, then another related to "it"
    ("Place the blue block, then the yellow block to its right, then the green block to the right of the yellow block.",
     ["right_of(green,yellow)", "right_of(yellow,blue)"]),
    # the start's top cube taken off a tower said in the same sentence, and put somewhere
    ("take the top cube off the orange-purple tower (orange at the bottom) and set it on the table",
     ["on_table(purple)", "start:stack(orange,purple)"]),
    ("Take the top cube off the purple on orange tower and put it on the red patch.",
     ["on_patch(purple,patch:red)", "start:stack(orange,purple)"]),
    ("Set the green block next to the tower made of a red block on top of a blue block.", ["next_to(blue,green)", "stack(blue,red)"]),
])
def test_stranger37s_ordinary_refusals_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_lower_case_question_without_its_mark_is_refused_as_a_question():
    with pytest.raises(Inexpressible) as exc:
        parse("what colour is the cube on top of the stack")
    assert exc.value.kind == "question"


@pytest.mark.parametrize("text", ["Build a pyramid where the base is red.", "Build a pyramid. The base is red."])
def test_a_pyramids_base_said_by_colour_is_its_whole_bottom_layer(text):
    # (one red cube had been put in the base and the other two given colours nobody said)
    bottom = meaning(parse(text))[0].split("(")[1].split("|")[0]
    assert bottom == "red,red,red"


def test_a_tower_listed_without_order_and_related_in_the_plane_stays_unordered():
    # "behind it" holds of every cube of a tower; the list says no order (red had been demanded at the bottom)
    s = parse("Build a tower of the red and blue blocks and put the green block behind it.")
    assert "any order" in s.goal_summary
    # (this one had been refused: the order said free and the tower read in order)
    s = parse("make a tower of red, green and blue, doesn't matter which order, and put yellow to the left of it")
    assert type(s.goal.children()[0]).__name__ == "UnorderedStack" and s.goal.children()[1].name == "left_of"


@pytest.mark.parametrize("text, expected", [
    # a voice's commentary around a task said in sentences of its own: dropped (each had been refused for its words)
    ("Stack the red cube on the blue cube. Wave goodbye to the audience.", ["stack(blue,red)"]),
    ("Put the red cube on the blue cube. What do you do?", ["stack(blue,red)"]),
    ("Ship's log. Put the gray cube in the front right corner of the table. Calm seas.", ["in_region(gray,front_right)"]),
])
def test_a_voices_commentary_sentences_are_dropped(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Stack the red cube on the blue cube. Mix well.",  # a verb that may change the scene
    "Stack the red cube on the blue cube. Under a maroon sky.",  # a colour the palette lacks
    "Stack the red cube on the blue cube. Never twice.",
    "Stack the red cube on the blue cube. Then celebrate.",  # a step after the task
    "Stack the red cube on the blue cube. Then scramble everything.",
])
def test_sentences_that_may_bear_on_the_goal_are_not_commentary(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # a voice's sentence of its own world, with a verb of its own and nothing that may refer to the task (read sets'
    # refusals, thirty-fourth session): its negation is that world's
    ("Whistle! Everybody out of the pool and listen up: stack the red cube on the blue cube, nice and steady. "
     "No running on deck!", ["stack(blue,red)"]),
    ("Returns desk: please put the brown cube on the orange patch. No late fees today.", ["on_patch(brown,patch:orange)"]),
    ("Stack the red block on the blue block. Headquarters is counting on you.", ["stack(blue,red)"]),
    ("Stack the red block on the blue block. Enjoy your stay.", ["stack(blue,red)"]),  # an imperative of regard
    ("Stack the red block on the blue block. Mind the gap.", ["stack(blue,red)"]),
    # a concession of the task's effort before it (held-out class: "while" had been refused as a time)
    ("It may take a while, but put the red cube on the blue cube.", ["stack(blue,red)"]),
    ("This is a bit tricky, but stack the green cube on the yellow cube.", ["stack(yellow,green)"]),
    # told by the speaker of themselves: its time is the speaker's
    ("Stack the red block on the blue block. I'll see you later.", ["stack(blue,red)"]),
    ("Stack the red block on the blue block. My train leaves soon.", ["stack(blue,red)"]),
])
def test_a_voices_sentence_of_its_own_world_is_dropped(text, expected):
    from rpg.schema.reading import normalize_words

    assert sorted(meaning(parse(text))) == expected
    assert normalize_words(text)[2]  # what was dropped is listed, not silently gone


@pytest.mark.parametrize("text", [
    "Stack the red block on the blue block. If there is room.",  # a condition
    "Stack the red block on the blue block. Do not move.",  # a verb that changes a scene
    "Stack the red block on the blue block. No touching.",  # contact between cubes
    "Stack the red block on the blue block. No wobbling.",  # the tower's standing
    "Stack the red block on the blue block. Don't hurry.",  # speed
    "Stack the red block on the blue block. Never again.",  # a repetition
    "Stack the red block on the blue block. Don't drop anything.",  # a pronoun for cubes
    "Stack the red block on the blue block. Then go and dry off.",  # a further step
    "Stack the red block on the blue block. Must be neighbours.",  # a requirement
    "Stack the red block on the blue block. Pick up a towel.",  # an imperative with a thing of the scene
    "Stack the red block on the blue block. Now leave the room.",
    "Stack the red block on the blue block. I need it done quickly.",  # the speaker's wish of the task ("it")
    "Stack the red block on the blue block. I'll check after ten seconds.",  # a time said in a number
    "Stack the red block on the blue block. You have until noon.",  # the listener's time, not the speaker's
    # a hostile helper's (thirty-fourth session), each had been dropped: said to the one who does the task, a short
    # negation, the speaker's clock time, wish or condition
    "Stack the red block on the blue block. Stay safe out there.",
    "Stack the red block on the blue block. Don't proceed.",
    "Stack the red block on the blue block. Pinch lightly.",
    "Stack the red block on the blue block. Await my signal.",
    "Stack the red block on the blue block. Keep going.",
    "Stack the red block on the blue block. Power down.",
    "Stack the red block on the blue block. No tools!",
    "Stack the red block on the blue block. No dawdling!",
    "Stack the red block on the blue block. Nobody budges.",
    "Stack the red block on the blue block. I need results by noon.",
    "Stack the red block on the blue block. I want no scratches.",
    "Stack the red block on the blue block. I'll pay double if you're early.",
    "Stack the red block on the blue block. Logos up.",
    "It should take under a minute, but put the red cube on the blue cube.",  # a time, no concession
])
def test_a_sentence_that_may_refer_to_the_task_is_no_voices_world(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # read development sets' refusals, twenty-seventh session
    ("The pink cube starts stacked on the black one. Unstack it and place it on the cyan patch.",
     ["on_patch(pink,patch:cyan)", "start:stack(black,pink)"]),
    ("The episode starts with the pink cube stacked on the brown cube; success requires the pink cube to be placed on the table.",
     ["on_table(pink)", "start:stack(brown,pink)"]),
    ("Goal: the letters B, E, D spelled out left to right.",
     ["line[left_to_right](B,E,D)", "reads(B,E,D;direction=left_to_right,face=up,text=BED)"]),
    ("Digits 3, 1, 2, left to right.", ["line[left_to_right](3,1,2)"]),
])
def test_starts_undone_by_unstack_it_and_label_lists_along_a_direction(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", ["build 3-stack, middle must be yellow", "build a stack of 3, middle must be yellow"])
def test_a_towers_middle_said_without_its_article(text):
    s = parse(text)
    assert len(set(s.goal_predicate().object_names())) == 3 and "with yellow second from the bottom" in s.goal_summary


@pytest.mark.parametrize("text, expected", [
    # a tower or row said cube by cube by ordinals: its colours in that order
    ("Build a tower of four: the first cube is white, the second black, the third white, the last black, counting from "
     "the bottom.", ["stack(white,black,white,black)"]),
    ("The first block of the tower (the bottom one) is purple, the second is pink and the third is purple again.",
     ["stack(purple,pink,purple)"]),
    ("Row of three, left to right: the first block is white, the second is black, the third is white.",
     ["line[left_to_right](white,black,white)"]),
    ("Build a tower of three. Counting from the top, the first cube is red, the second is blue, the third green.",
     ["stack(green,blue,red)"]),
])
def test_structures_said_by_ordinals(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    "Make a row of three: the first block is white, the second is black, the third is white.",  # which end is first?
    "Build a tower: the first cube is red, the third is blue.",  # a gap in the ordinals
])
def test_ordinals_without_an_end_or_with_a_gap_are_refused(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Stack the three red cubes into a tower, then crown it with the yellow cube.", ["stack(red,red,red,yellow)"]),
    ("Stack red on blue and top it off with a green cube.", ["stack(blue,red,green)"]),
    ("Dump all the cyan cubes in a heap on the left side.", ["pile(cyan,cyan,cyan)@left"]),
    ("Tuck the red cube behind the blue cube.", ["behind(red,blue)"]),
])
def test_crown_it_with_dump_and_tuck(text, expected):
    assert meaning(parse(text)) == expected


@pytest.mark.parametrize("text", [
    # a hostile helper's attack on this session's readings: each had compiled silently wrong, now refused
    "You have a red cube and a blue cube. Put it on the green patch.",  # "it" of two cubes
    "There are three blue cubes on the table. Place both of them on the blue patch.",  # "both" of three
    "There are two blue cubes and one red cube. Put both on the blue patch.",
    "There is a blue cube on the table. Place both of them on the blue patch.",
    "Place the blue block, then the yellow block to its right, each on the green patch",  # "each" had been dropped
    "Place the blue block, then the yellow block to its right, then the red block to its right",  # which "its"?
    "Set the green block next to the tower made of wood.",  # a tower invented
    "Set the green block next to the tower made of red blocks.",
    "build 3-stack, middle must be yellow, top must be red",  # red had gone to the bottom
    "build 3-stack of blue cubes, middle must be yellow",  # a red cube invented
    "Stack red on blue. Just kidding.", "Stack red on blue. Ignore that.", "Stack red on blue. April fools.",
    "Build a tower of three. Counting from the top, the first cube (the bottom one) is red, the second is blue, the third green.",
    "Build a tower of four: the first cube is white, the second black, the third white, the next-to-last black, counting "
    "from the bottom.",
    "Row of three, left to right: the first block is white, the second is black, the third is red, counting from the right.",
    "Build a tower of three: the first cube is red, the second blue, the third green, counting from the left.",
])
def test_this_sessions_readings_attacked_refuse(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    # taken off the start's stack and put in a place of the table: on the table there (it could have stayed on its base)
    ("The pink cube starts stacked on the black one. Unstack it and place it in the left half.",
     ["in_region(pink,left)", "on_table(pink)", "start:stack(black,pink)"]),
    ("The episode starts with the pink cube stacked on the brown cube; success requires the pink cube to be placed on the "
     "table in the back left corner.", ["in_region(pink,back_left)", "on_table(pink)", "start:stack(brown,pink)"]),
])
def test_taken_off_and_put_in_a_place_stays_on_the_table(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_step_after_a_listed_stack_leaves_its_order_free():
    s = parse("Stack the red and blue blocks, then put yellow on the table next to the green block.")
    assert "any order" in s.goal_summary


@pytest.mark.parametrize("text, expected", [
    # what is there now, one cube on another, then a command moving the top one: the start (the stack had been the goal
    # and "it" the stack)
    ("There is a red cube on top of the blue cube. Put it on the green patch.", ["on_patch(red,patch:green)", "start:stack(blue,red)"]),
    ("The red cube is stacked on the blue cube. Put it on the green patch.", ["on_patch(red,patch:green)", "start:stack(blue,red)"]),
    ("There is a red cube on top of the blue cube. Put it on the table.", ["on_table(red)", "start:stack(blue,red)"]),
])
def test_a_start_said_as_what_is_there_now(text, expected):
    assert sorted(meaning(parse(text))) == expected


def test_a_stack_said_with_another_cube_moved_stays_the_goal():
    assert sorted(meaning(parse("The red cube is stacked on the blue cube. Put the green cube next to it."))) == [
        "next_to(blue,green)", "stack(blue,red)"]


@pytest.mark.parametrize("text, expected", [
    ("Build a tower of number blocks with 1 at the bottom, then 2, then 3 on top.", ["stack(1,2,3)"]),
    ("Build a tower of letter cubes: A at the bottom, then B, then C on top.", ["stack(A,B,C)"]),
    # a start said as what sits there, then a cube put on top and the tower restated
    ("A green block sits on a brown block. Put a gray block on top so the tower is brown, green, gray.",
     ["stack(brown,green,gray)", "start:stack(brown,green)"]),
    # the restated tower without its direction: it runs from the cube put on top (a fourth cube had been made)
    ("Put a gray block on top so the tower is brown, green, gray.", ["stack(brown,green,gray)"]),
])
def test_label_towers_from_the_bottom_and_restated_towers(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Initially green is on brown. Put a gray block on top so the tower is gray, green, brown.",  # not that tower
    "Put a gray block on top so the tower is green, gray, brown.",  # gray at neither end
    "Put the red cube and the blue cube on different patches.",  # which patch each? (both had gone on one gray patch)
])
def test_restated_towers_that_disagree_and_unnamed_patches_are_refused(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("new task -> red near blue, green far from both", ["far_from(blue,green)", "far_from(green,red)", "next_to(blue,red)"]),
    ("pile - 4 brwon cubes - back right", ["pile(brown,brown,brown,brown)@back_right"]),
    ("note for Tues demo - put the yelow cube on top of the green one, then both of them on the blue patch",
     ["on_patch(green,patch:blue)", "stack(green,yellow)"]),
])
def test_far_from_both_a_specs_last_place_and_a_stack_then_onto_a_patch(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", ["Put the yellow block on them.", "Put the yellow block next to them."])
def test_them_with_one_cube_named_is_refused(text):
    # (a red and a blue cube had been made up for "them")
    with pytest.raises(Inexpressible) as exc:
        parse(text)
    assert exc.value.kind == "reference"


@pytest.mark.parametrize("text, expected", [
    # classes a helper reported from the session's unread set (these examples are the helper's own)
    ("Stack for the test. Base: red. Next: white. Top: green.", ["stack(red,white,green)"]),  # (white had been dropped)
    ("Tower. Base: blue. Then: yellow. Top: black.", ["stack(blue,yellow,black)"]),
    ("Tower task. Base: red. Next: white. Next: blue. Top: green.", ["stack(red,white,blue,green)"]),
    ("build a tower: red first, then white on it, then blue on the white", ["stack(red,white,blue)"]),  # (a green cube made up)
    ("Set the red cube in the gap between the blue cube and the yellow cube.", ["between(red;blue,yellow)"]),
    ("For this trial the red cube should end up on the blue cube.", ["stack(blue,red)"]),
    ("Put the green cube balanced on the red cube.", ["stack(red,green)"]),
    ("put the white cube in the back right corner and the gray cube right next to it",
     ["in_region(white,back_right)", "next_to(gray,white)"]),
    ("a line running front to back: yellow at the front, then gray, then pink", ["line[front_to_back](yellow,gray,pink)"]),
    ("line of three cubes from left to right with red on the left, then white, then blue", ["line[left_to_right](red,white,blue)"]),
])
def test_the_unread_sets_classes_read(text, expected):
    assert sorted(meaning(parse(text))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Tower. Top: black. Next: yellow. Base: blue.",  # a cube between the roles said top first: where?
    "line of three cubes from left to right with red on the right, then white, then blue",
])
def test_roles_between_ends_said_top_first_and_an_end_against_the_direction_are_refused(text):
    with pytest.raises(BadInput):
        parse(text)


def test_a_cube_picked_by_its_place_now_is_refused_as_a_reference_to_the_current_scene():
    with pytest.raises(Inexpressible, match="current scene") as exc:
        parse("Put the rightmost cube on the green cube.")
    assert exc.value.kind == "reference"


@pytest.mark.parametrize("text, expected", [
    ("Make one pile of the two green cubes and another pile of the two white cubes.", ["pile(green,green)", "pile(white,white)"]),
    ("Task: a row of five cubes. Two blue on the left, then one yellow, then two blue on the right.",
     ["line[left_to_right](blue,blue,yellow,blue,blue)"]),
    ("Put the pink cube left of the gray cube and the cyan cube right of the gray cube, all three in a row.",
     ["line[left_to_right](pink,gray,cyan)"]),
    ("Front to back: yellow first, then red, then green last.", ["line[front_to_back](yellow,red,green)"]),
])
def test_counted_piles_counted_row_groups_and_sides_in_a_row(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text", [
    # a second hostile helper's attack on the session's latest readings: each had compiled silently wrong
    "Tower. Base: red. Next: any. Top: green.",  # the middle dropped
    "Tower. Base: red. Top: green. Next: white.",  # white had gone above the top
    "Tower. Base: red. Next: white. Top: green, then blue.",
    "Put two gray blocks on top so the tower is brown, gray, gray.",  # a five-cube tower
    "Put a gray block at the bottom so the tower is brown, green, gray.",
    "A row of six cubes. Two blue on the left, then one yellow, then two blue on the right.",  # a second, random row
    "Build a tower of four: the first cube is white, the second black, the third white, the top black, counting from the top.",
    "Stack red on blue. Topsy turvy.",
])
def test_the_latest_readings_attacked_refuse(text):
    with pytest.raises(BadInput):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Tower. Base: red cube. Next: white cube. Then: blue cube. Top: green cube.", ["stack(red,white,blue,green)"]),
    ("The red cube lies on the blue cube. Put it on the green patch.", ["on_patch(red,patch:green)", "start:stack(blue,red)"]),
    # a start said as a plain fact, then a move of its top cube (once refused: both had been demanded)
    ("The red cube is on the blue cube. Move the red cube behind the blue cube.", ["behind(red,blue)", "start:stack(blue,red)"]),
    ("There is a red cube on top of the blue cube. Put the blue cube on the green patch.",
     ["on_patch(blue,patch:green)", "start:stack(blue,red)"]),
    ("Put a gray block on top so the tower is brown, green, gray and the pink cube on the red patch.",
     ["on_patch(pink,patch:red)", "stack(brown,green,gray)"]),
])
def test_the_latest_readings_attacked_read(text, expected):
    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    # twenty-eighth session, from stranger38 (read): a stressed relation after a cube placed in a corner ("it" was lost)
    ("ok so the red cube goes in the back right corner and the yellow cube goes right next to it",
     ["in_region(red,back_right)", "next_to(red,yellow)"]),
    ("Put the red cube in the center and the blue cube directly to the left of it", ["in_region(red,center)", "left_of(blue,red)"]),
    # a diagonal said by a corner's name or by two relations together: the two relations, a diagonal pair
    ("goal: blue cube diagonally in front of and to the right of the red cube", ["in_front_of(blue,red)", "right_of(blue,red)"]),
    ("Put the blue cube to the front-right of the red cube.", ["in_front_of(blue,red)", "right_of(blue,red)"]),
    ("Put the 5 block to the back-left of the 2 block.", ["behind(5,2)", "left_of(5,2)"]),
    ("Put the red cube to the right front of the blue cube", ["in_front_of(red,blue)", "right_of(red,blue)"]),
    ("Put the red cube to the back right of the letter A", ["behind(red,A)", "right_of(red,A)"]),
    ("Put the blue cube in the center and the red cube to the front-right of it.",
     ["in_front_of(red,blue)", "in_region(blue,center)", "right_of(red,blue)"]),
    # "it" after a cube placed in a place is that cube only where no other cube is said between
    ("Put the red cube in the center and the blue cube left of yellow and behind it.",
     ["behind(blue,yellow)", "in_region(red,center)", "left_of(blue,yellow)"]),
    ("Task: a horizontal row of five cubes. Two white on the left, then one red, then two white on the right.",
     ["line[left_to_right](white,white,red,white,white)"]),
    ("Put the red cube on the blue cube. Thank you ever so much.", ["stack(blue,red)"]),  # thanks, no quantity
    ("Now, dear, would you kindly set the grey block over by the left side of the table? Thank you ever so much.",
     ["in_region(gray,left)"]),
])
def test_stressed_relations_diagonal_pairs_and_idle_commentary(text, expected):
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    if "diagonal" in text or "front-right" in text or "back-left" in text or "right front" in text:
        assert all(getattr(p, "diagonal", False) for p in schema.goal.children() if p.name in ("in_front_of", "behind", "left_of", "right_of"))  # each relation leaves the other axis free


@pytest.mark.parametrize("text, kind", [
    ("Put the blue cube diagonally behind the red cube.", "action"),  # which side? a pose word alone stays refused
    ("Put the blue block to the top left of the red block.", None),  # a map's "top": above, or behind?
    ("Stack the red blocks. As many as you can.", "quantity"),
    ("Put the red cube on the blue cube. Avoid collisions.", "negation"),  # a negation still keeps its sentence
    ("Put the red cube on the blue cube. Mix well.", "action"),
    ("Stack red on blue. Once more.", None),
    ("Stack red on blue. If it falls, retry.", "condition"),
    # a sentence that names no cube may still bear on the task with a quantity, a time or a condition (a hostile
    # helper's attack on a rule that had dropped such sentences mid-session, reverted)
    ("Build a tower of blue cubes. Several levels, please.", "quantity"),
    ("Build a line of red cubes. Use plenty.", "quantity"),
    ("Put the red cube on the blue cube. There is a strict time limit.", None),
    ("Put the red cube on the blue cube. Do so if the gripper is free.", "condition"),
    ("Put the red cube on the blue cube. Call the clinic if symptoms persist.", "condition"),
    # a hostile helper's attack on the diagonal and "it" readings: each had compiled silently wrong mid-session
    ("Put the red cube to the back-right of the blue patch.", None),  # a blue cube had been made up
    ("Move the cube to the front-right of the blue cube onto the green cube.", None),  # a cube picked by its place
    ("Put the red cube in the front and the blue cube away from green next to it.", None),
    ("Lay out the blue blocks in an arrow shape pointing left.", "shape"),
    ("Arrange the blocks in the shape of a boat.", "shape"),
])
def test_diagonal_words_and_pointing_commentary_still_refused(text, kind):
    with pytest.raises(BadInput) as e:
        parse(text)
    if kind is not None:
        assert isinstance(e.value, Inexpressible) and kind in {k for k, _, _ in e.value.reasons}


@pytest.mark.parametrize("text", [
    # a hostile helper's finds, each silently wrong at the session's start
    "Put the blue cube nowhere near the red cube.",  # had been next_to: "nowhere" dropped
    "Put the blue cube nowhere behind the red cube.",
    "Stack the red cube on the blue cube. Unstack.",  # "Unstack." had been dropped as framing
    "Stack the red cube on the blue cube. Add two more.",  # more cubes than named, dropped
    "Stack the red cube on the blue cube. Add another on top.",
    "Stack the red cube on the blue cube. Make three of these.",
    "Put the red cube in front of and the green cube to the right of the blue cube.",  # had been in_front_of(red,green)
])
def test_dropped_negations_removals_extra_cubes_and_gapped_relations_refuse(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a second structure said "another one of ...": two towers (one tower of six had been read)
    ("build a tower of red, blue and green, then another one of yellow, pink and white",
     ["stack(red,blue,green)", "stack(yellow,pink,white)"]),
    ("Build a tower of red, blue and green. Then build another tower of yellow, pink and white.",
     ["stack(red,blue,green)", "stack(yellow,pink,white)"]),
    ("Stack the red cube on the blue cube. Add another red cube on top.", ["stack(blue,red,red)"]),
    ("put one more blue block next to the red block", ["next_to(blue,red)"]),
])
def test_another_structure_and_named_extra_cubes_are_read(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # a helper's abstract classes of stranger39's silent errors, with its own examples
    ("four yellow cubes in a column, moving away from the robot", ["line[front_to_back](yellow,yellow,yellow,yellow)"]),
    ("a column of three cyan cubes going toward the robot", ["line[back_to_front](cyan,cyan,cyan)"]),  # (read as front to back reversed)
    ("a row of three white cubes running away from the robot", ["line[front_to_back](white,white,white)"]),
    ("stack three red cubes in a column", ["stack(red,red,red)"]),
    ("Make a row of three with the white cube in the middle and one black cube on each side.",
     ["line[left_to_right](black,white,black)"]),  # a red cube had been made up
    ("Make a row of three cubes, one blue on each side of the red one.", ["line[left_to_right](blue,red,blue)"]),  # (green)
    ("Build a row of three red cubes toward the robot.", ["line(red,red,red)@front"]),  # "toward the robot" had been dropped
    ("a pyramid with 3 blue cubes at the bottom, then 2 green cubes, then 1 red cube on top", ["pyramid(blue,blue,blue|green,green|red)"]),
])
def test_columns_running_from_the_robot_and_rows_with_a_middle_cube(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # a base of three and one cube on top: those two layers, the top cube centred over the base (a middle layer had been
    # made up, then it was refused; twenty-ninth session: Pyramid(layers=(3, 1)))
    ("Make a pyramid whose base is three cubes (pink, orange, cyan) with a white cube at the apex.", ["pyramid(cyan,orange,pink|white)"]),
    ("a pyramid with white, pink and cyan forming the base and a gray cube at the top", ["pyramid(cyan,pink,white|gray)"]),
    ("pyramid: bottom layer pink, orange, cyan; top layer white", ["pyramid(cyan,orange,pink|white)"]),
    ("Build a pyramid with pink, orange and cyan on the bottom and red on top.", ["pyramid(cyan,orange,pink|red)"]),
    ("Build a pyramid. Base: pink, orange, cyan. Top: red.", ["pyramid(cyan,orange,pink|red)"]),
    ("Pyramid task: bottom layer purple, purple, brown; top layer blue.", ["pyramid(brown,purple,purple|blue)"]),
    ("build a two-level pyramid: three yellow cubes on the bottom layer and one red cube on top", ["pyramid(yellow,yellow,yellow|red)"]),
    ("The cube pyramid has a base of three cubes (red, red, blue) and a single yellow cube on top of them.",
     ["pyramid(blue,red,red|yellow)"]),
])
def test_a_pyramid_of_a_base_under_one_cube_is_those_two_layers(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []
    pyramid = next(p for p in schema.goal_predicate().walk() if type(p).__name__ == "Pyramid")
    assert pyramid.layers == (pyramid.base, 1)


@pytest.mark.parametrize("text", [
    "Build a pyramid whose base is red and blue on top.",  # the base's cubes unsaid
    "Build a pyramid with red, green and blue on the bottom and a yellow and a pink cube on top.",  # two on top
    "a pyramid with three cubes on the bottom (red, green, blue), a white one on top and a pink one next to it",
])
def test_a_pyramid_of_a_base_under_one_cube_with_its_cubes_unsaid_is_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a helper's abstract classes of stranger39's refusals, with its own examples
    ("In a single line, put the gray cube at the far left, the pink cube in the center and the green cube at the far right.",
     ["line[left_to_right](gray,pink,green)"]),  # the ends and the middle are the ordered row's, not regions
    ("a line of five: an orange cube in the middle, two brown cubes on each side", ["line[left_to_right](brown,brown,orange,brown,brown)"]),
    # a start said as what is there now, then a cube put on its top cube
    ("The green cube sits on the blue cube. Put the white cube on top of the green cube.",
     ["stack(blue,green,white)", "start:stack(blue,green)"]),
    ("The red cube is on the blue cube. Put the green cube on the red cube.", ["stack(blue,red,green)", "start:stack(blue,red)"]),
])
def test_row_ends_as_sides_counted_sides_and_starts_topped(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []  # every demand of the goal cites words of the text (a reading can be right and
    # its citations fail: "Right now ..." had been read by the parser and refused by the citations' reading)


def test_a_start_said_as_the_scene_now_is_the_start_only_before_a_command_on_its_top_cube():
    # "Currently" / "Right now" before what the start reader reads is that start; the goal's citations read the words after
    # the opening; elsewhere the scene now stays refused (which words are the goal's?)
    for text in ("Right now the green cube sits on the blue cube. Put the white cube on top of the green cube.",
                 "Currently the green cube is on the blue cube. Add the white cube on top of the green cube."):
        schema = check_feasibility(parse(text))
        assert sorted(meaning(schema)) == ["stack(blue,green,white)", "start:stack(blue,green)"]
        assert uncited(schema) == []
    for text in ("Currently the red cube is on the blue cube. Put the green cube on the yellow patch.",
                 "Currently the red cube is on the blue cube. Put the blue cube on the green patch."):
        with pytest.raises(BadInput):
            parse(text)


def test_opposite_corners_with_far_from_each_other_is_far_from():
    # the corners only say how far apart ("far from each other" says the relation); alone they stay unread
    text = "Keep the gray cube and the orange cube at opposite corners of the table, far from each other."
    assert sorted(meaning(check_feasibility(parse(text)))) == ["far_from(gray,orange)"]
    with pytest.raises(BadInput):
        parse("put the gray cube and the orange cube at opposite corners")


def test_a_pyramid_whose_base_is_not_said_keeps_its_default_size_with_a_top_cube():
    # the skipped-layer refusal is only for a base said (it had refused this, and a steering edit with it)
    assert meaning(check_feasibility(parse("a pyramid with a red cube on top"))) == ["pyramid(blue,green,yellow|orange,purple|red)"]


@pytest.mark.parametrize("text", [
    # a second hostile helper's attack on the column, start and pyramid readings (each had compiled silently wrong)
    "The green cube sits on the blue cube. Put the white cube on top of the green cube, then put the whole tower on the red cube.",
    "Build a pyramid whose base is red and blue on top.",  # (once read with a middle layer of colours nobody said)
    "Build a tower of red and blue. Build another one.",  # the second tower had been dropped
])
def test_the_latest_readings_attacked_again_refuse(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a column kept upright by its words is no line ("stacked"; "move it away": the column moved)
    ("Make a column of four yellow cubes, moving away from the robot, stacked.", ["stack(yellow,yellow,yellow,yellow)@back"]),
    ("The green cube sits on the blue cube. Put the white cube on top of the green cube. Then put the blue cube on the red cube.",
     ["stack(red,blue,green,white)"]),  # no start read where more is said after the topping
])
def test_columns_kept_upright_and_starts_read_only_when_the_topping_ends_the_text(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # twenty-ninth session, from stranger39 (read as development material)
    ("Make a line running from front to back: blue nearest the robot, then yellow, then red farthest away.",
     ["line[front_to_back](blue,yellow,red)"]),  # the ends' marks said again (blue had been left out)
    ("Arrange the blocks in a line so that green is leftmost, then blue, then pink, with red rightmost.",
     ["line[left_to_right](green,blue,pink,red)"]),
    ("Place three cubes in a row; the rightmost is pink, next to it is orange, and the leftmost is gray.",
     ["line[right_to_left](pink,orange,gray)"]),
    ("I want a stack of three: the cyan cube goes on the table first, the brown one goes on it, and the gray one finishes the tower.",
     ["stack(cyan,brown,gray)"]),
    ("stack the blocks so that white is on top, purple is at the bottom and green is between them", ["stack(purple,green,white)"]),
    ("Make a row of five cubes with a black cube in the middle and two white cubes on each side of it.",
     ["line[left_to_right](white,white,black,white,white)"]),
    ("Swap places: the yellow cube goes on the cyan patch and the cyan cube goes on the yellow patch.",
     ["on_patch(cyan,patch:yellow)", "on_patch(yellow,patch:cyan)"]),
])
def test_row_ends_marked_again_towers_finished_and_swaps_said_by_places(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "Place four cubes in a row; the rightmost is pink, next to it is orange, and the leftmost is gray.",  # a cube unsaid
    "Arrange the blocks in a line so that green is leftmost, then blue, then pink, with red leftmost.",  # one end twice
    "Make a row of five cubes with a black cube in the middle and one white cube on each side of it.",  # 3 of 5 said
    "Swap places: the yellow cube goes on the cyan patch.",  # the other cube's place unsaid
    "Make a line running from back to front: blue nearest the robot, then yellow, then red farthest away.",  # ends crossed
])
def test_row_ends_and_swaps_that_leave_a_cube_unsaid_are_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    # twenty-ninth session: a hostile helper's attack on the session's readings and a helper's probes of stranger40 (each
    # had compiled silently wrong)
    "Build a pyramid: three cubes on the bottom (red, green, blue) and a yellow cube on top, sitting on the red and green cubes.",
    "Build a pyramid: three yellow cubes on the bottom layer and one red cube on top. Make another pyramid just like it.",
    "Build a tower of red on blue. Make another tower just like it.",  # (one tower had been built)
    "Build a pyramid: three cubes on the bottom (red, green, blue) and one yellow cube above them.",  # a middle layer made up
    "Build a pyramid with a yellow cube on top and red, green and blue below it.",
    "Build a pyramid: three cubes on the bottom, red, green and blue, and the yellow cube on top.",
    "Build a pyramid: blue, green and pink on the bottom, red on top, and orange in the middle.",  # one orange made two
    "Build a pyramid: the bottom has red, green and blue, the second layer has white and black, and the top has yellow.",
    "Stack the red cube on the blue cube. No reds.",  # a commentary sentence about the cubes
    "Stack the red cube on the blue cube. Not necessary.",
    "Stack the red cube on the blue cube. Would skip.",
    "Make a line running from front to back: blue nearest the robot, then yellow, and red farthest from the yellow cube.",
    "Make a line of red, green and blue from left to right. Green is rightmost.",  # a role after the line contradicts it
    "Place three cubes in a row; the rightmost is pink, next to it is orange, and the leftmost is gray. The rightmost is orange.",
    "Make a row of five cubes with a black cube in the middle and two white cubes on each side of it. The middle is white.",
    "The black cube glides from the left of the white cube.",  # where it starts, not where it ends
    "The black cube travels from the left of the white cube to the green patch.",
    "Take the black cube out from under the white cube.",  # (it had been put on top of it)
    "Place the tall red block behind the green block.",  # a size
    "Take down the tower.",  # an undoing of a tower nobody described (a tower had been built)
])
def test_the_twenty_ninth_session_s_attacks_are_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Form a row moving away from the robot: pink, then yellow, then white.", ["line[front_to_back](pink,yellow,white)"]),
    ("A wall two rows high, each row three green blocks wide.", ["wall(green,green,green,green,green,green)"]),
    ("Take down the stack of blue on yellow so both end up on the table.", ["on_table(blue)", "on_table(yellow)", "start:stack(yellow,blue)"]),
    ("Hey! Your job is to put the red cube on the blue cube.", ["stack(blue,red)"]),  # ("Your" had lost its "Yo")
    ("The black cube glides to the left of the white cube.", ["left_of(black,white)"]),
    ("Make a line of red, green and blue from left to right. Blue is rightmost.", ["line[left_to_right](red,green,blue)"]),
])
def test_the_twenty_ninth_session_s_attacks_read_right(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text, expected", [
    # a helper's abstract classes of stranger40's ordinary refusals, with its own examples
    ("Pyramid: bottom row orange, orange, orange; middle row pink, pink; top row cyan.",
     ["pyramid(orange,orange,orange|pink,pink|cyan)"]),  # a pyramid's rows are its layers
    ("Make a wall of three green blocks with three orange blocks on top of them.", ["wall(green,green,green|orange,orange,orange)"]),
    ("Unstack the 2-block stack of blue on yellow so both cubes are on the table.", ["on_table(blue)", "on_table(yellow)", "start:stack(yellow,blue)"]),
    ("Build a tower: blue at the bottom, red at the top, and yellow wedged in between.", ["stack(blue,yellow,red)"]),
    ("Arrange the cubes in a row so the cyan cube is at the far left, the pink cube is at the far right and the brown cube is "
     "in the middle.", ["line[left_to_right](cyan,brown,pink)"]),
    ("Slide the green cube to the back edge of the table, far from the robot.", ["in_region(green,back)"]),
    ("There's a tower of the pink cube on the yellow cube. Put the brown cube on top.",
     ["stack(yellow,pink,brown)", "start:stack(yellow,pink)"]),
    ("Build a pyramid with a bottom row of four cubes.", ["pyramid(red,red,red,red,red,red,red,red,red,red)"]),  # base 4
])
def test_stranger40_s_ordinary_classes_read_right(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


def test_which_cube_goes_at_the_bottom_left_free_is_a_stack_in_any_order():
    schema = check_feasibility(parse("Stack the red and the yellow cube; which one goes at the bottom isn't important."))
    assert [type(p).__name__ for p in schema.goal_predicate().walk()] == ["UnorderedStack"]


@pytest.mark.parametrize("text, expected", [
    # voices' frames and asides (a helper's classes of stranger40's voice refusals, with its own examples)
    ("For triple credit, put the red cube on the cyan patch.", ["on_patch(red,patch:cyan)"]),
    ("Whip up a tower of the pink cube on the yellow cube.", ["stack(yellow,pink)"]),
    ("Relax and put the pink cube on the yellow cube.", ["stack(yellow,pink)"]),
])
def test_voices_frames_read_right(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "Line up the red cubes in a row, no gaps.",  # an aside about the cubes' spacing
    "Put the red cube on the blue cube, not the green one.",
    "Put the red cube on the blue cube, no stacking.",
    "Put the red cube on the blue cube, then wave at the camera.",  # a further step: an action
    # a rule that dropped sentences and trailing asides talking of a topic of their own ("No smokers.", ", no pressure")
    # was reverted: a hostile helper's attack showed such topics stand for the task's ("No neighbours.", "No penthouse.",
    # ", no doubles", "Due by lunchtime.", "Must be neighbours.")
    "Put the red cube left of the blue cube. No neighbours.",
    "Stack the red cube on the blue cube. No penthouse.",
    "Three orange cubes in a line, no doubles.",
    "Stack the red cube on the blue cube. Due by lunchtime.",
    "Put the red cube left of the blue cube. Must be neighbours.",
    "The dumb idea is to put the red cube on the blue cube.",  # (an 'idea' frame was reverted too)
    "Zoom in on the green block on the blue patch.",  # camera talk ('zoom' is no placement)
])
def test_trailing_asides_that_bear_on_the_task_stay_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    # a second hostile helper's attack on the session's later readings (each had compiled silently wrong)
    "Build two pyramids: bottom row orange, orange, orange; middle row pink, pink; top row cyan.",  # one had been built
    "Build a pyramid: bottom row orange, orange, orange; middle row pink, pink.",  # a red top had been made up
    "Stack the red and the yellow cube; which one goes at the bottom isn't important, but yellow.",  # a third cube
])
def test_the_second_attack_on_the_session_s_readings_is_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Take the stack of blue on yellow down so both end up on the table.", ["on_table(blue)", "on_table(yellow)", "start:stack(yellow,blue)"]),
    ("A wall two rows high, each row three blocks wide.", ["wall(red,red,red,red,red,red)"]),  # no colour asked of a row
])
def test_the_second_attack_on_the_session_s_readings_reads_right(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    # silent errors of the session's start the attacks found (pre-existing)
    "Three orange cubes in a line, four actually.",  # a count said again after a comma (it had been dropped)
    "Three orange cubes in a line, make it five.",
    "Move the black cube to the left of the white cube until it touches the red cube.",  # (white had been put next to red)
])
def test_afterthought_counts_and_touching_after_a_relation_are_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


def test_a_count_in_and_a_cube_slid_until_it_touches_still_read():
    assert meaning(check_feasibility(parse("Slide the red block until it touches the blue block."))) == ["next_to(blue,red)"]
    assert meaning(check_feasibility(parse("Build two towers of two cubes each, one all green and one all pink."))) == [
        "stack(green,green)", "stack(pink,pink)"]


@pytest.mark.parametrize("text", [
    # pre-existing silent errors the attacks found, refused now
    "Stack the red cube on the blue cube. Needs a roof.",  # another cube on top, nobody named (it had been dropped as idle)
    "Stack the red cube on the blue cube. Must have a hat.",
    "Put every cube to the left of the white cube.",  # all the scene's cubes (one red cube had been made up)
    "Put every cube on the blue patch.",
])
def test_needs_and_every_cube_of_the_scene_are_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # "in a row"'s "a" had read as a letter label, so the goal had kept cubes of its own (a red one made up)
    ("Unstack the stack of blue on yellow so both cubes are in a row.", ["line(blue,yellow)", "start:stack(yellow,blue)"]),
    ("Initially yellow is on red. Put both cubes in a row.", ["line(red,yellow)", "start:stack(red,yellow)"]),
    ("Put every cube on the patch of its own colour: red ones on the red patch, green ones on the green patch.",
     ["on_patch(green,patch:green)", "on_patch(red,patch:red)"]),
])
def test_the_start_s_cubes_in_a_row_and_each_cube_on_its_own_patch(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


def test_a_cube_put_in_one_place_then_another_is_refused():
    # the first place had been kept ("then to its right" dropped)
    with pytest.raises(BadInput, match="in one place and then in another"):
        parse("Put the black cube to the left of the white cube, then to its right.")
    assert meaning(check_feasibility(parse("Put the red cube on the blue cube, then the green cube on the red cube."))) == [
        "stack(blue,red,green)"]
    assert sorted(meaning(check_feasibility(parse("Place each block on the patch of the same color")))) == [
        "on_patch(blue,patch:blue)", "on_patch(red,patch:red)"]  # each cube's own patch, not every cube of the scene


@pytest.mark.parametrize("text, expected", [
    ("Put the letter cubes B, A and T in a row, any order", ["line(A,B,T)"]),
    ("Line up the digit cubes 4, 1 and 7 in any order", ["line(1,4,7)"]),
])
def test_labelled_cubes_in_a_row_in_any_order_are_unordered(text, expected):
    """Labelled cubes listed "in any order" had been held to the listed order from either end (the
    middle cube fixed: stricter than the words)."""
    from rpg.schema.meaning import meaning

    assert sorted(meaning(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    # a line going away from the robot whose ends are marked "nearest" / "furthest" (the first cube had been dropped)
    ("Put three cubes in a line going away from the robot: blue nearest, then red, then green furthest.",
     ["line[front_to_back](blue,red,green)"]),
    # "which one is on top doesn't matter": the order left free (refused as a negation)
    ("Make a tower out of the pink block and the black block; which one is on top doesn't matter.", ["stack(pink,black)"]),
    # a bare side after a list of colours: the table's side (the list's commas had read as another clause)
    ("Pile up the orange, cyan and white cubes in the back.", ["pile(cyan,orange,white)@back"]),
    # "sandwiched between them": the tower's middle
    ("Build a tower where the orange cube is the base, the white cube is on top, and the cyan cube is sandwiched between them.",
     ["stack(orange,cyan,white)"]),
    # "digit cube 3 at the bottom, 8 in the middle and 1 on top" (the noun before the label had doubled "digit")
    ("Build a tower with digit cube 3 at the bottom, 8 in the middle and 1 on top.", ["stack(3,8,1)"]),
    ("Stack the cubes from bottom to top: digit 1, digit 2, digit 3.", ["stack(1,2,3)"]),  # ("the cubes" had been a red cube)
    # digits given roles (once a tower of four, the 4 invented by the sorted-tower reader; then refused)
    ("Stack the digit cubes with 3 on the bottom, 2 in the middle and 1 on top.", ["stack(3,2,1)"]),
    # "near the robot, at the front edge": one place said twice (refused as a repeated object)
    ("Put the black block near the robot, at the front edge of the table.", ["in_region(black,front)"]),
    # a wall's first course said "in one layer"
    ("a wall of four white blocks in one layer with four pink blocks on top of them", ["wall(white,white,white,white|pink,pink,pink,pink)"]),
])
def test_stranger40_constructions(text, expected):
    """stranger40 (the twenty-ninth session's transfer measure, read in the thirtieth): its ordinary refusals."""
    from rpg.schema.meaning import meaning

    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


def test_all_cubes_but_some_is_not_read_as_those_cubes():
    """"Stack all cubes but the white ones into a tower" must not become a tower of the white ones."""
    with pytest.raises((ParseError, Inexpressible)):
        parse("Stack all cubes but the white ones into a tower.")


@pytest.mark.parametrize("text, expected", [
    # a wall's size in number words (it had been dropped: the default 3x2 wall, silently wrong)
    ("Put up a three-by-three wall of cyan cubes.", ["wall(" + ",".join(["cyan"] * 9) + ")"]),
    ("Build a wall of orange blocks, two by two.", ["wall(orange,orange,orange,orange)"]),
    # a start stack, then every cube on the table: the bottom one too (it had been left out)
    ("Start: the pink cube is on the orange cube, which is on the red cube. Goal: all three cubes on the table.",
     ["on_table(orange)", "on_table(pink)", "on_table(red)", "start:stack(red,orange,pink)"]),
    # "line up ... going away from the robot": a line from front to back (it had been an unordered line in the back)
    ("Line up the pink, cyan and white cubes going away from the robot.", ["line[front_to_back](pink,cyan,white)"]),
    ("Please line up two cubes going away from the robot: purple nearest, white furthest.", ["line[front_to_back](purple,white)"]),
    # a tower's labels listed from the top ("digit" before each had read them upward)
    ("Stack the cubes from top to bottom: digit 1, digit 2, digit 3.", ["stack(3,2,1)"]),
    # a row in a region, "in any order" after the place
    ("Put the red, blue and gray cubes in a row at the back of the table, in any order.", ["line(blue,gray,red)@back"]),
    # a pyramid layer listing a colour twice among others
    ("Build a pyramid: base orange, gray, orange; second layer white, white; peak purple.", ["pyramid(gray,orange,orange|white,white|purple)"]),
    # letters in a row "reading" a word: the word's order
    ("Build a row of the letter cubes T, A and B, reading BAT", ["line[left_to_right](B,A,T)", "reads(B,A,T;direction=left_to_right,face=up,text=BAT)"]),
])
def test_stranger41_classes(text, expected):
    """The silent errors and refusals a helper reported, as abstract classes with examples of its
    own, of stranger41 (the thirtieth session's transfer measure), and the attack on the session's changes."""
    from rpg.schema.meaning import meaning

    schema = parse(text)
    assert sorted(meaning(schema)) == expected


@pytest.mark.parametrize("text", [
    "Build a tower with digit cube 3 at the bottom, red in the middle and 1 on top.",  # (red had been dropped)
    "Build a tower with digit cube 3 at the bottom, 12 in the middle and 1 on top.",  # (a 2 had been made up)
    "Put letter cubes C, A, T in a row in any order, reading CAT",  # (read as CAT left to right)
    "Put the letter cubes A, B and C in a row in any order, facing up",
    "Build a row of the letter cubes T, A and B, reading CAT",  # (no C: read TAB)
])
def test_labels_given_places_they_cannot_have_are_refused(text):
    with pytest.raises((ParseError, Inexpressible)):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("Currently pink rests on gray. Unstack both.", ["on_table(gray)", "on_table(pink)", "start:stack(gray,pink)"]),
    ("Currently pink is on gray. Unstack it.", ["on_table(gray)", "on_table(pink)", "start:stack(gray,pink)"]),
    ("The red cube is on the blue cube. Unstack them.", ["on_table(blue)", "on_table(red)", "start:stack(blue,red)"]),
    ("Currently pink is on gray. Take it off.", ["on_table(pink)", "start:stack(gray,pink)"]),
])
def test_a_start_said_now_then_undone(text, expected):
    """A start said as the scene now ("Currently pink rests on gray.", bare colours), then undone by "Unstack both/them/it"
    (refused before: the start had not been read without articles, and "both" not as the stack's cubes)."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


def test_the_towers_middle_said_before_its_ends():
    """"The middle cube of the tower is pink; gray is at the base and white at the top": the tower the text goes on to
    describe (refused before as a tower nobody described); a tower named with nothing else said of it stays refused."""
    for text in ("The middle cube of the tower is pink; gray is at the base and white at the top.",
                 "The middle of the tower should be the pink cube; gray goes on the bottom and white goes on top."):
        schema = parse(text)
        assert sorted(meaning(schema)) == ["stack(gray,pink,white)"]
        assert uncited(schema, text) == []
    with pytest.raises((ParseError, Inexpressible)):
        parse("Put the red cube on top of the tower.")


@pytest.mark.parametrize("text, expected", [
    ("Put a green cube on each of the two patches, the red patch and the blue patch.",
     ["on_patch(green,patch:blue)", "on_patch(green,patch:red)"]),
    ("Put a green cube on each of the red and blue patches, and a red cube on the yellow patch.",
     ["on_patch(green,patch:blue)", "on_patch(green,patch:red)", "on_patch(red,patch:yellow)"]),
    ("Put a pink cube on each of the red, green, blue and yellow patches.",
     ["on_patch(pink,patch:blue)", "on_patch(pink,patch:green)", "on_patch(pink,patch:red)", "on_patch(pink,patch:yellow)"]),
])
def test_a_cube_on_each_of_two_patches_named(text, expected):
    """"a green cube on each of the red and blue patches": one green cube on each patch named (refused before: how many
    patches, or each patch said twice); a third patch listed is not cut off (refused, not read as two)."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []
    with pytest.raises((ParseError, Inexpressible)):
        parse("put a green cube on each of the red patch and the blue patch and the yellow patch")


def test_a_cube_moved_from_the_start_stack():
    """"There is a stack of blue on red. Move the blue cube from the stack onto the yellow patch.": "from the stack" is the
    start's stack (refused before as a cube picked by where it stands); said with no start, it stays refused."""
    text = "There is a stack of blue on red. Move the blue cube from the stack onto the yellow patch."
    schema = parse(text)
    assert sorted(meaning(schema)) == ["on_patch(blue,patch:yellow)", "start:stack(red,blue)"]
    assert uncited(schema, text) == []
    with pytest.raises((ParseError, Inexpressible)):
        parse("Move the blue cube from the stack onto the yellow patch.")


@pytest.mark.parametrize("text, expected", [
    ("In this environment, the green cube must end up in the right half of the table.", ["in_region(green,right)"]),
    ("This tutorial task asks the agent to stack the red cube on the blue cube.", ["stack(blue,red)"]),
    ("The policy is evaluated on placing the blue cube between the red and yellow cubes.", ["between(blue;red,yellow)"]),
])
def test_a_papers_framing_of_the_task(text, expected):
    """How a paper frames a task ("In this environment, ...", "This tutorial task asks the agent to ...", "The policy is
    evaluated on placing ...") had been refused for 'environment', 'agent', 'evaluated'; a colour before "task" is not
    dropped as framing (refused), and a negation after the framing stays refused."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []
    for refused in ("This red task asks the robot to stack the blue cube on the green cube.",
                    "In this environment, do not put red on blue."):
        with pytest.raises((ParseError, Inexpressible)):
            parse(refused)


@pytest.mark.parametrize("text, expected", [
    ("Two rows: three red cubes at the front and three blue cubes at the back.",
     ["line(blue,blue,blue)@back", "line(red,red,red)@front"]),
    ("Place one cube on each patch: red cube on the blue patch, blue cube on the red patch.",
     ["on_patch(blue,patch:red)", "on_patch(red,patch:blue)"]),
])
def test_a_heading_said_again_by_its_parts(text, expected):
    """"Two rows: <one group>, <another>" (no structure had been read) and "one cube on each patch: <each cube's patch>"
    (refused as each said twice); three rows said for two groups, or two cubes on one patch under "each patch", stay
    refused."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []
    for refused in ("Three rows: three red cubes and three blue cubes.",
                    "Place one cube on each patch: red cube on the blue patch, blue cube on the blue patch."):
        with pytest.raises((ParseError, Inexpressible)):
            parse(refused)


@pytest.mark.parametrize("text, expected", [
    ("Put the red cube and the blue cube next to the cyan cube.", ["next_to(blue,cyan)", "next_to(cyan,red)"]),
    ("Bring both purple cubes next to the cyan cube.", ["next_to(cyan,purple)", "next_to(cyan,purple)"]),
    ("Put the red and blue cubes behind the yellow cube.", ["behind(blue,yellow)", "behind(red,yellow)"]),
])
def test_a_relation_said_of_two_cubes_at_once(text, expected):
    """"the red cube and the blue cube next to the cyan cube": the relation holds for each (refused before: one cube had no
    place, or "both purple cubes" was read as one); two cubes put "on" one cube stay refused (which is on top?)."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []
    with pytest.raises((ParseError, Inexpressible)):
        parse("Put the red cube and the blue cube on the cyan cube.")


@pytest.mark.parametrize("text, expected", [
    ("Orange cube put behind green cube, cyan cube put in front green cube.", ["behind(orange,green)", "in_front_of(cyan,green)"]),
    ("Brown cube go next to white cube, and red cube go to back.", ["in_region(red,back)", "next_to(brown,white)"]),
    ("The brown cube is next to the white cube, and the red cube is at the back.", ["in_region(red,back)", "next_to(brown,white)"]),
])
def test_terse_places_with_a_word_dropped_or_a_verb_said(text, expected):
    """"in front green cube" (an 'of' dropped), "go to back" (an article dropped) and a last clause's side said with a verb
    ("and the red cube is at the back"): refused before as a cube with no place; a side after a tower's clause, which may
    be the tower's, stays refused."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []
    with pytest.raises((ParseError, Inexpressible)):
        parse("Put the blue cube on the green cube, and the red cube goes in front.")


@pytest.mark.parametrize("text, expected", [
    ("start: green on brown. goal: green on table", ["on_table(green)", "start:stack(brown,green)"]),
    ("1. Start: orange cube sitting on top of the pink cube. 2. Goal: both cubes on the table.",
     ["on_table(orange)", "on_table(pink)", "start:stack(pink,orange)"]),
])
def test_a_start_and_goal_said_tersely(text, expected):
    """"goal: green on table" (the table's article dropped: read as the start's tower) and a start and goal numbered as
    steps ("1. Start: ... 2. Goal: ...": the goal had been read alone)."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "Put a green cube on each of the red and red patches",  # (two cubes on one patch)
    "Put a green cube on each of the red and blue patches and put the red cube on it.",  # (on which green cube?)
    "There is a red cube on the green patch. Move the blue cube from the stack onto the yellow patch.",  # (no stack said)
    "There is a stack of blue on red. Move the green cube from the stack onto the yellow patch.",  # (green not in it)
    "The middle of the tower should be the green cube; blue goes on the bottom.",  # (two cubes have no middle)
    "The middle of the tower should be the wooden cube; blue goes on the bottom and red goes on top.",
    "The middle of the tower should be the green cube; green goes on the bottom and red goes on top.",
    "The middle of the tower should be the green cube; blue goes on the bottom and red goes on top. The tower has five cubes.",
    "The bottom of the tower should be the green cube; blue goes on the bottom and red goes on top.",
    "This undo task asks the agent to stack the red cube on the blue cube.",  # (the framing word changes the task)
    "The previous task asks the agent to stack the red cube on the blue cube.",
    "Put the green cube on the red patch; the cube on the red patch should be big",  # (old: 'big' dropped, a cube made up)
    "Put the green cube on the red patch. The cube should be big.",  # (old: the sentence dropped)
])
def test_this_sessions_readings_refuse_what_they_cannot_place(text):
    """Attacks on this session's readings (a stranger's, 2026-11-26): each compiled something the words did not say."""
    with pytest.raises((ParseError, Inexpressible)):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Build upward from red block through green block to blue block.", ["stack(red,green,blue)"]),
    ("Create a three-level stack with blue block supported by green block, which is supported by red block.",
     ["stack(red,green,blue)"]),
    ("Position red block, green block, and blue block from left to right in the specified sequence.",
     ["line[left_to_right](red,green,blue)"]),
    ("Place red block to the left, green block in the middle, and blue block on the right in a linear fashion.",
     ["line[left_to_right](red,green,blue)"]),
])
def test_a_templates_words_for_towers_and_rows(text, expected):
    """A benchmark template's words ("build upward from ... through ... to ...", "supported by", "in the specified
    sequence", "in a linear fashion") had been refused (development split)."""
    schema = parse(text)
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text, expected", [
    # a voice's label before its task and a simile or aside at a sentence's end (each had been refused for its words)
    ("Pottery class, week nine: stack the yellow cube on the black cube, like a fresh glaze.", ["stack(black,yellow)"]),
    ("Harbour master's bulletin: the green cube goes behind the red cube, as per the mooring chart.", ["behind(green,red)"]),
    ("Put the white cube next to the pink cube, calm as two oars in a boat.", ["next_to(pink,white)"]),
    ("Line up the cyan, brown and gray cubes in a row like ducklings following their mother.", ["line(brown,cyan,gray)"]),
    ("Bakery notice: put the orange cube on the purple patch - the ovens are warm today.", ["on_patch(orange,patch:purple)"]),
    ("Docket 48. Place the blue cube in the front left corner of the table, where the kettle would be.",
     ["in_region(blue,front_left)"]),
    ("Place the pink cube between the red cube and the blue cube, the way a good host greets guests.",
     ["between(pink;blue,red)"]),
])
def test_a_voices_label_and_sentence_tails_are_dropped(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "Stack red on blue, like last time.",  # a reference
    "Put the red cube in front of the blue cube, like in the picture.",
    "Stack the red cube on the blue cube, like a tall chimney.",  # a size in the simile (the chimney stays, refused)
    "Put the red cube next to the blue cube, in the bowl.",  # a place that is an object
    "Put the red cube on the blue cube, using the tongs.",  # a tool
    "Put the red cube next to the blue cube, upside down.",
    "Put the red cube next to the blue cube, then knock it over.",
    "Without help: put the red cube on the blue cube.",  # a negation in a label
    "Put the red cube on the blue cube, if the light is on.",  # a condition
    "Stack red on blue - the way you did it before.",
    "Put the red cube left of the blue cube, as far as possible.",
    "Stack the red cube on the blue cube, like the green tower.",  # a colour and a structure in the simile
    "Put the red cube on the blue cube, spiral shape please.",  # a shape
    "Put the red cube on the blue cube, textbook!",  # a word alone may carry meaning
    # a hostile helper's probes: a simile or label that carries a relation, an order, a shape, a judgement or a viewpoint
    "Put the red cube next to the blue cube, like a hat on a head.",
    "Stack the red cube on the blue cube, like a traffic light.",
    "Stack the red cube on the blue cube, like stairs.",
    "Bad example: put the red cube on the blue cube.",
    "Inverse version: put the red cube on the blue cube.",
    "Time permitting: put the red cube on the blue cube.",
    "Put the red cube left of the blue cube, looking from the door.",
    "Put the red cube next to the blue cube, slightly offset.",
    "Stack the red cube on the blue cube, like we practised.",
])
def test_a_chunk_that_may_bear_on_the_goal_is_no_voice(text):
    """A chunk at a task's edge that says anything the goal may hang on stays, to be read or refused."""
    from rpg.schema.feasibility import InfeasibleTask

    with pytest.raises((ParseError, Inexpressible, InfeasibleTask)):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Stack the letter cubes so that, reading from bottom to top, they go T, O, P.", ["stack(T,O,P)"]),
    ("Move the orange block to the far side of the table, away from the robot.", ["in_region(orange,back)"]),
    ("Put the red and the blue cubes onto the yellow and green patches, respectively.",
     ["on_patch(blue,patch:green)", "on_patch(red,patch:yellow)"]),
])
def test_a_chunk_of_the_task_at_a_sentences_end_is_kept(text, expected):
    """A label cube's letter, "away from the robot" and "respectively" end sentences too: they are the task's."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # development sets' refusals and one silent error (thirty-second session), in words of the tests' own
    ("Both the blue and the yellow cube should be behind the gray cube.", ["behind(blue,gray)", "behind(yellow,gray)"]),
    ("The pink and cyan cubes go next to the brown cube.", ["next_to(brown,cyan)", "next_to(brown,pink)"]),
    ("We need a tower of two red cubes with a white cube on top.", ["stack(red,red,white)"]),
    ("The yellow cube should end up at the front of the table, near the robot.", ["in_region(yellow,front)"]),
    ("Build a tower of gray (bottom) and pink (top).", ["stack(gray,pink)"]),
    ("Build a tower of gray (bottom), cyan and pink (top).", ["stack(gray,cyan,pink)"]),
    ("Stack three cubes so that red is the base, blue sits on red and green crowns the tower.", ["stack(red,blue,green)"]),
    ("Put blue on red and white on top.", ["stack(red,blue,white)"]),
    # (two cubes on one, or two chains, leave "on top" unplaced: refused, test below)
    # a start said in other words than the start reader's own
    ("Initial setup: a stack with green at the bottom and white on top. Add a black cube on top of the white one.",
     ["stack(green,white,black)", "start:stack(green,white)"]),  # (black had gone on white alone: green free to leave)
    ("At the start the cyan cube is on the brown cube. Reverse the tower.", ["stack(cyan,brown)", "start:stack(brown,cyan)"]),
    ("Initially the red cube sits on the blue cube, which sits on the green cube. Unstack the whole tower.",
     ["on_table(blue)", "on_table(green)", "on_table(red)", "start:stack(green,blue,red)"]),
    ("Currently the red cube sits on the blue cube, which sits on the green cube. Unstack the whole tower.",
     ["on_table(blue)", "on_table(green)", "on_table(red)", "start:stack(green,blue,red)"]),
    ("Currently there is a tower of black, white, pink from bottom to top. Unstack it so every cube is on the table.",
     ["on_table(black)", "on_table(pink)", "on_table(white)", "start:stack(black,white,pink)"]),  # "there is" said now
    # a text that is only a tower's roles (no task had been found)
    ("Top: red. Middle: green. Bottom: blue.", ["stack(blue,green,red)"]),
    ("Bottom: blue, top: red.", ["stack(blue,red)"]),
    ("Upper cube: red. Lower cube: blue.", ["stack(blue,red)"]),
    # a text that is the tower said without a verb, its cubes in turn (no task found, or "above it" put green on top)
    ("A tower with blue at the bottom, green above it and red on top.", ["stack(blue,green,red)"]),
    # a start tower, its top cube taken off and set beside it (the start had been read as the goal: a contradiction)
    ("A tower of red on blue stands on the table. Take the red cube off and put it to the right of the blue cube.",
     ["right_of(red,blue)", "start:stack(blue,red)"]),
    ("The red block sits on top of the blue block. Move the red block off and set it to the left of the blue block.",
     ["left_of(red,blue)", "start:stack(blue,red)"]),
    ("A tower, blue at the base and red on it.", ["stack(blue,red)"]),
    ("The final scene shows a tower, blue at the base and red on it.", ["stack(blue,red)"]),  # ("shows" had left an "s")
])
def test_compound_subjects_counted_towers_glosses_and_starts_in_other_words(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "In case the red cube is on the left, put it on the blue patch.",  # a condition
    "Currently the red cube is next to the blue cube. Put the green cube on the yellow cube.",  # the scene now, no stack
    "Currently the red cube is on the blue cube and the room is dark. Put the green cube on the yellow cube.",
    # the scene now said with "there is" before a goal of other cubes: red on blue had become part of the goal
    "Right now there is a red cube on the blue cube. Stack the green cube on the yellow cube.",
    "There is now a red cube on the blue cube. Stack the green cube on the yellow cube.",
    "Top: red. Middle: blue.",  # no bottom
    "Top: red. Top: blue.",
    "Currently there is a red cube on the blue cube. Stack the green cube on the yellow cube.",
])
def test_in_case_and_a_scene_now_that_is_no_start_are_refused(text):
    from rpg.schema.feasibility import InfeasibleTask

    with pytest.raises((ParseError, Inexpressible, InfeasibleTask)):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # cubes named after the colon that "them" stands for; the far end said again of a row said from one side; a goal said
    # by its means (thirty-second session, development sets)
    ("Line them up from the left: the gray cube first, then the cyan cube, then the brown cube at the right end.",
     ["line[left_to_right](gray,cyan,brown)"]),
    ("Line up the cubes from the right: the gray cube first, then the cyan cube, then the brown cube at the left end.",
     ["line[right_to_left](gray,cyan,brown)"]),
    ("Initially the pink block is on the yellow block; clear the yellow block by putting the pink block on the table.",
     ["on_table(pink)", "start:stack(yellow,pink)"]),
    ("Free the blue cube by moving the red cube onto the green patch.", ["on_patch(red,patch:green)"]),
])
def test_them_before_a_colons_list_a_rows_far_end_and_a_goal_said_by_its_means(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "Line up the cubes from the right: the gray cube first, then the cyan cube, then the brown cube at the right end.",
    "Put them in a row: the gray cube.",  # one cube after the colon: "them" still names nothing
    "Clear the blue cube by knocking the red cube over.",
])
def test_a_far_end_that_contradicts_them_with_one_cube_and_a_means_outside_the_domain_are_refused(text):
    from rpg.schema.feasibility import InfeasibleTask

    with pytest.raises((ParseError, Inexpressible, InfeasibleTask)):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # classes a helper reported from a held-out set (thirty-second session), in words of the tests' own
    ("Set a cyan cube on top of two stacked red cubes.", ["stack(red,red,cyan)"]),  # (it had been silently stack(red,cyan))
    ("Put the white block onto three blue blocks stacked together.", ["stack(blue,blue,blue,white)"]),
    ("Set a cyan cube under two stacked red cubes.", ["stack(cyan,red,red)"]),  # (a hostile helper's: a red had been dropped)
    # said as the goal, with no verb, or of a tower (thirty-fourth session: a held-out set's silent error, a red dropped)
    ("Goal: the cyan cube on top of two stacked red cubes.", ["stack(red,red,cyan)"]),
    ("The cyan cube should end up on top of two stacked red cubes.", ["stack(red,red,cyan)"]),
    ("Build a tower with the cyan cube on top of two stacked red cubes.", ["stack(red,red,cyan)"]),
    ("Make a tower: cyan block on top of two stacked red blocks.", ["stack(red,red,cyan)"]),
])
def test_a_cube_on_top_of_counted_stacked_cubes(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


@pytest.mark.parametrize("text", [
    "Put the blue cube next to the pink cube on top of two stacked red cubes.",
    # a hostile helper's (thirty-fourth session): more cubes after the stacked ones (blue had gone on top of cyan), two
    # such towers in one sentence (each had one red), a tower's labels said in turn with a place after the last (a
    # contradiction had been reversed, or coloured cubes made up), labelled cubes given a colour (a blue cube added)
    "Goal: the cyan cube on top of two stacked red cubes and a blue cube.",
    "Goal: the cyan cube on top of two stacked red cubes, the green cube on top of two stacked blue cubes.",
    "Build a tower of letter blocks: A at the bottom, then B, then C at the bottom.",
    "Build a tower of number blocks: 7 at the bottom, then 2, then 9 at the bottom.",
    "Build a tower of number blocks: 7 at the bottom, then 2, then 9 in the corner.",
    "Build a tower of blue number blocks: 7 at the bottom, then 2, then 9.",
])
def test_counted_stacked_cubes_or_label_steps_the_reading_does_not_take_are_refused(text):
    """'two stacked red cubes' counts red cubes: a reading with one red is refused, not compiled (it had been)."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    "Stack the cyan cube and the pink cube. Which one goes on top is up to you.",  # (it had been ordered, cyan at the bottom)
    "Stack the cyan cube and the pink cube; it is up to you which one goes on top.",
    "Stack the pink and gray blocks, either way round.",
])
def test_which_cube_goes_on_top_left_to_the_reader_is_no_order(text):
    assert [type(p).__name__ for p in parse(text).goal_predicate().walk()] == ["UnorderedStack"]


def test_somewhere_other_than_a_place_is_a_negation():
    with pytest.raises(Inexpressible, match="negation"):
        parse("Place the pink cube somewhere other than the left half of the table.")


def test_an_unordered_line_or_circle_matches_its_cubes_in_any_order():
    assert matches("circle(gray,cyan,pink)", ["circle(cyan,gray,pink)"])
    assert matches("line(gray,cyan,pink)@back", ["line(cyan,gray,pink)@back"])
    assert not matches("line[left_to_right](gray,cyan,pink)", ["line[left_to_right](cyan,gray,pink)"])


@pytest.mark.parametrize("text, expected", [
    ("When you're ready, put the red cube on the blue cube.", ["stack(blue,red)"]),  # a condition on the listener
    ("Put the red cube on the blue cube, whenever you're ready.", ["stack(blue,red)"]),
    ("Today's exercise is a tower of red and blue.", ["stack(red,blue)"]),
    ("A cyan cube is already on a pink cube. Add an orange cube on top of the cyan one.",
     ["stack(pink,cyan,orange)", "start:stack(pink,cyan)"]),
])
def test_a_listeners_readiness_a_days_task_and_a_stack_there_already(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert uncited(schema, text) == []


def test_a_condition_on_a_cube_being_ready_stays_refused():
    with pytest.raises(Inexpressible, match="conditional"):
        parse("If the red cube is ready, put it on the blue cube.")


@pytest.mark.parametrize("text", [
    # a hostile helper's silent errors against this session's readings, each refused now
    "Build a tower: brown (bottom) and yellow (top) and red (middle).",  # (red had gone on top)
    "Green and red sit on blue and white goes on top.",  # (a red on green had been made up)
    "Green sits on blue and red sits on yellow and white goes on top.",  # (which tower's top?)
    "Both the red and the orange cube should be next to the white cube and the black cube.",  # (red-black had been lost)
    "I'd like a tower of two green cubes with an orange cube on top of the table.",
    "Clear the white block by putting the green block on the white block.",
])
def test_this_sessions_readings_attacked_are_refused(text):
    from rpg.schema.feasibility import InfeasibleTask

    with pytest.raises((ParseError, Inexpressible, InfeasibleTask)):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Put the red cube on the blue cube, then the green one at the top.", ["stack(blue,red,green)"]),
    ("Red on blue, and green at the very top.", ["stack(blue,red,green)"]),
    ("Red sits on blue and green goes on the very top.", ["stack(blue,red,green)"]),
    # the top of the table is its back; a corner is a corner
    ("Put the red cube on the blue cube, and the green cube at the very top of the table.",
     ["in_region(green,back)", "stack(blue,red)"]),
])
def test_a_cube_at_the_very_top_after_a_chain_tops_its_tower(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


def test_a_cube_at_the_top_with_a_corner_is_not_put_on_the_tower():
    from rpg.schema.feasibility import InfeasibleTask

    with pytest.raises((ParseError, InfeasibleTask)):
        check_feasibility(parse("Put red on blue, and green at the top left corner."))


@pytest.mark.parametrize("text", [
    "Stack the cube closest the robot on the blue cube.",
    "Stack the cube nearest the robot on top of the blue cube.",
    "Stack the cube nearest you on the blue cube.",
    "Stack the red cube nearest the blue cube on the green cube.",
])
def test_a_cube_picked_by_what_it_stands_nearest_is_refused_after_stack(text):
    """"stack" had passed for a structure described, so "the cube closest the robot" was read as a part of it (and
    "closest" then as "close": a next_to and a default red cube, silently; a stranger set's must-refuse text)."""
    with pytest.raises(Inexpressible, match="current scene"):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("The tower should be: red at the bottom, blue above it, green above that.", ["stack(red,blue,green)"]),
    ("The tower should be red at the bottom, blue above it and green above that.", ["stack(red,blue,green)"]),
    ("The final state is a tower: red at the bottom, blue above it, green above that, yellow on top.",
     ["stack(red,blue,green,yellow)"]),
    ("It should be a tower with red at the bottom, blue above it, and green on top.", ["stack(red,blue,green)"]),
])
def test_a_tower_declared_cube_by_cube_reads_each_cube_above_the_one_before(text, expected):
    """Without a verb before the tower, "above that" had been read above the first cube and the rest ordered at will."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # either cube on top: the order left free
    ("Stack the red and blue cubes; either can be on top.", "UnorderedStack"),
    ("Stack the red and blue cubes, either of them may sit on top.", "UnorderedStack"),
    # a person other than the robot doing the task
    ("The student should stack the red cube on the blue cube.", "Stack"),
    ("The participant has to put the red cube left of the blue cube.", "LeftOf"),
])
def test_either_on_top_and_a_student_doing_the_task_are_read(text, expected):
    assert expected in {type(p).__name__ for p in parse(text).goal_predicate().walk()}


@pytest.mark.parametrize("text, expected", [
    ("Put the red cube at the back of the table, far from the robot.", ["in_region(red,back)"]),
    ("Put the red cube at the back of the table (far from the robot).", ["in_region(red,back)"]),
    ("Stack red on blue at the back of the table, away from the robot.", ["stack(blue,red)@back"]),
    # the corner said, then its side from the robot: the goal holds both, the corner (meaning() had written the side)
    ("Put the red cube at the back right corner, far from the robot.", ["in_region(red,back_right)"]),
    ("Put the red cube in the back right corner, at the back of the table.", ["in_region(red,back_right)"]),
])
def test_a_side_said_again_from_the_robot_is_the_same_place(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    ("Righto, pop the red cube on top of the blue one.", ["stack(blue,red)"]),
    ("Righto put the red cube on the blue cube.", ["stack(blue,red)"]),
    ("put the bluee cube on the red cube", ["stack(red,blue)"]),  # a typo still corrected
])
def test_a_word_that_begins_with_a_place_word_is_not_corrected_into_it(text, expected):
    """"Righto" had been corrected to "right", a place the task then lacked (refused) or, elsewhere, took."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    # "at the very top" without a chain before it is a place of the table, not the top of a tower
    "Put the red cube in the bottom left corner and the blue cube at the very top",
    "Put red in the middle, then the blue one at the top",
    # a cube on top and a place after it: of the cube or of the tower? (the top had been dropped, silently)
    "Put red on blue, then the green one at the very top, next to yellow",
    "Put red on blue, then green on top, in the back left corner",
    "Stack red on blue with green on top, on the yellow patch",
    # cubes said in turn on the one before with more around them (another reader had ordered them at will, silently)
    "The tower: red at the bottom, blue above it, green above that.",
    "Build a tower. Red at the bottom, blue above it, green above that.",
    "The tower should be red at the bottom, blue above it, green above that, on the green patch",
    "Put red on the green patch, blue above it, green above that",
    # "either can be on top of green": green's place is said (the order had been freed for all three)
    "Stack red and blue; either can be on top of green",
])
def test_the_session_s_attack_on_new_readings_is_refused(text):
    """A hostile helper's probes of the thirty-third session's readings that had compiled to what the words do not say."""
    from rpg.schema.feasibility import InfeasibleTask

    with pytest.raises((ParseError, InfeasibleTask)):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Put red on blue, then put green in the back left corner", ["in_region(green,back_left)", "stack(blue,red)"]),
    ("Put red on blue, then green in the front left corner.", ["in_region(green,front_left)", "stack(blue,red)"]),
    ("Put red on blue, then the green one in the center", ["in_region(green,center)", "stack(blue,red)"]),
    # the tower put there is the tower's place
    ("Stack red on blue, then put the tower in the back left corner.", ["stack(blue,red)@back_left"]),
])
def test_a_bare_colour_placed_after_a_chain_goes_there_alone(text, expected):
    """"then put green in the back left corner" had added green to the tower and sent the whole tower to the corner."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "Stack red and blue. Stack green and yellow.",
    "Stack red and blue, then stack green and yellow",
    "Stack the red and blue blocks. Stack the green and yellow blocks separately.",
])
def test_two_stacking_commands_each_naming_its_cubes_make_two_towers(text):
    """One tower of all four had been read (its order freed), silently (found by this session's attack)."""
    towers = sorted(sorted(p.objects) for p in parse(text).goal_predicate().walk() if type(p).__name__ == "UnorderedStack")
    assert towers == [["blue", "red"], ["green", "yellow"]]


@pytest.mark.parametrize("text, expected", [
    ("Initially red is on blue with green on top. Put yellow on orange.", ["stack(orange,yellow)", "start:stack(blue,red,green)"]),
    ("Initially the red cube sits on the blue cube with a green cube on top. Move the green cube onto the yellow patch.",
     ["on_patch(green,patch:yellow)", "start:stack(blue,red,green)"]),
    ("Start: a blue cube with the white cube on top of it. Put the white cube on the table.",
     ["on_table(white)", "start:stack(blue,white)"]),
])
def test_a_start_chain_with_a_cube_on_top_puts_it_on_the_chain_s_top(text, expected):
    """"red is on blue with green on top" had started blue, green, red (green on blue, the chain's bottom)."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


def test_a_start_chain_with_a_cube_on_top_of_it_is_refused():
    """"it" may be either cube of the chain (it had been read as the bottom one, silently)."""
    with pytest.raises(ParseError):
        parse("Initially red is on blue with green on top of it. Put yellow on orange.")


def test_a_pyramid_of_cubes_said_one_by_one_that_no_pyramid_has_is_refused():
    """Four cubes said one by one had made a base of 3 with a middle layer of colours nobody named (found by this
    session's attack); three said so are a pyramid of 3."""
    with pytest.raises(ParseError, match="3, 6, 10 or 15"):
        parse("Make a pyramid of red, blue and green with yellow on top")
    assert meaning(check_feasibility(parse("Make a pyramid of red, blue and green"))) == ["pyramid(blue,green,red)"]


@pytest.mark.parametrize("text, expected", [
    ("Tower A: orange, purple. Tower B: cyan, brown, red.", ["stack(cyan,brown,red)", "stack(orange,purple)"]),
    ("Tower 1: red, green. Tower 2: blue, yellow.", ["stack(blue,yellow)", "stack(red,green)"]),
    ("Stack 1: red, green. Stack 2: blue, yellow.", ["stack(blue,yellow)", "stack(red,green)"]),
    ("Two towers. Tower one, bottom to top: orange, purple. Tower two, bottom to top: cyan, brown, red.",
     ["stack(cyan,brown,red)", "stack(orange,purple)"]),
    ("Tower 1 (top to bottom): orange, purple. Tower 2 (top to bottom): cyan, brown, red.",
     ["stack(purple,orange)", "stack(red,brown,cyan)"]),
    ("Build two towers. Build a tower of red and green. Build another tower of blue and yellow.",
     ["stack(blue,yellow)", "stack(red,green)"]),
])
def test_towers_named_and_listed_are_each_a_tower(text, expected):
    """Two named towers' lists had been one tower of all their cubes, silently ("Tower A: orange, purple. Tower B: ...");
    a list without its direction leaves that tower's order free."""
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    if "bottom" not in text and "top" not in text:
        assert all(type(p).__name__ != "Stack" for p in schema.goal_predicate().walk())


@pytest.mark.parametrize("text", [
    "Build two towers. Build a tower of red and green.",
    "Build three towers. Tower A: orange, purple. Tower B: cyan, brown, red.",
])
def test_a_count_of_towers_said_before_fewer_towers_is_refused(text):
    """The towers the count had beyond those described were made up of blue cubes nobody named, silently."""
    with pytest.raises(ParseError, match="counts"):
        parse(text)


@pytest.mark.parametrize("text, expected", [
    ("The grey block should end up underneath the red block, with the red one resting on it.", ["stack(gray,red)"]),
    ("First put the white block down, then stack the black block on it, and finally the red block on the black one.",
     ["stack(white,black,red)"]),
    ("Lab note: the target is a two-high tower, white cube under the brown cube.", ["stack(white,brown)"]),
    ("Currently the pink cube is on the purple cube. Add the cyan cube on top of the pink one.",
     ["stack(purple,pink,cyan)", "start:stack(purple,pink)"]),
    ("Stack red, then green, then blue, each one on the previous.", ["stack(red,green,blue)"]),
    ("Lay the blocks out left to right as orange, orange, blue.", ["line[left_to_right](orange,orange,blue)"]),
    ("send the purple block to the back of the table", ["in_region(purple,back)"]),
    ("Put the red cube on the blue target.", ["on_patch(red,patch:blue)"]),
])
def test_phrasings_of_a_read_set_compile_to_what_they_say(text, expected):
    """Each had been refused: "it" was the cube just named (red on red), "First" kept the chain from being read, "the
    target is" had made a patch, "the pink one" kept the start from being read, "the previous" had no order, "lay out"
    and "send" were no verbs of a row or a move."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "Put red on blue, then green on the previous one.",
    "Stack red, then green, then blue, each one left of the previous.",
    "The scene we want at the end has a single blue cube in the middle of the table and two orange cubes on either side of "
    "it, one to its left and one to its right.",
])
def test_a_previous_cube_or_its_side_not_said_by_a_list_stays_refused(text):
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    "Build 0 towers.", "Build 100 towers.", "Build 20 towers.", "Build -1 towers.", "0 towers.", "Build 0 towers of 3.",
])
def test_a_count_of_towers_no_task_can_hold_is_one_line_not_a_traceback(text):
    """Each had crashed (ZeroDivisionError, ValueError from zip): found by this session's attack."""
    with pytest.raises(ParseError, match="towers"):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    "Tower 1: red. Tower 2: blue.",
    "Tower A - red, green. Tower B - blue, yellow.",
    "Tower I: red, green. Tower II: blue, yellow.",
    "Tower A: red, green, Tower B: blue, yellow.",
    "Build two towers. Build a tower of red and green. Then put the white cube next to the tower.",
    "Build one tower. Build a tower of red and green. Build another tower of blue and yellow.",
    "Build two towers. A tower of red and green.",
    "Build a tower of red and green. Build another tower of blue and yellow. Red on top.",
    "Build a tower of red and green. Build another tower of blue and yellow. Put the white cube next to the red cube.",
    "Stack white, then black on top, then brown.",
    "Put the white block down, then stack the black block on top, then the brown block.",
    "Stack red, then green, then blue, each one on the next.",
    "Stack red, then green, then blue, each one on the first.",
    "Stack red, then green, then blue, each one on the last.",
])
def test_towers_merged_made_up_or_topped_out_of_order_are_refused(text):
    """Each had compiled silently wrong (found by this session's attack): named towers' lists merged into one tower, a
    count of towers beside the towers said making up towers of cubes nobody named, two towers joined by a later sentence,
    a cube said 'on top' before more cubes put under the next one, 'each on the next' read as 'each on the previous'."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Build a tower of red and green. Build another tower of blue and yellow. Put the white cube on the white patch.",
     ["on_patch(white,patch:white)", "stack(blue,yellow)", "stack(red,green)"]),
    ("Tower A: red, green. Tower B: blue, yellow. Two towers.", ["stack(blue,yellow)", "stack(red,green)"]),
    ("Build two towers. A tower of red and green. A tower of blue and yellow.", ["stack(blue,yellow)", "stack(red,green)"]),
    ("towers-2: tower A = pink on white; tower B = black on orange", ["stack(orange,black)", "stack(white,pink)"]),
    # two towers said, four had been made (two of cubes nobody named), then it was refused: each tower now
    ("Level 7: Build two towers. Tower A: yellow, brown (bottom to top). Tower B: pink, cyan, white (bottom to top).",
     ["stack(pink,cyan,white)", "stack(yellow,brown)"]),
    ("Stack white, then black, then brown on top.", ["stack(white,black,brown)"]),
])
def test_towers_said_one_by_one_beside_a_patch_or_a_count_that_agrees_stay_apart(text, expected):
    """A cube put on a patch after two towers had joined them into one tower of four, silently."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "Make a circle of four and another circle of four",
    "Make one pile of red and green and one of blue and yellow",
    "Put red on green. Put white on green.",
    "Stack red on green and blue on green",
    "Stack red on green and blue on yellow, both on the blue patch",
    "Stack red on green and white on black. All on the blue patch.",
    "Stack red on green and blue on yellow and put them on the white patch",
    "Build two towers of three cubes, both on the white patch",
])
def test_structures_merged_dropped_or_left_off_their_patch_are_refused(text):
    """Each had compiled silently wrong (found by this session's second attack): two circles or piles said and one made,
    a second cube put on a cube another was on slid between them, 'both on the blue patch' put one tower there, a patch
    nobody named made up for the other tower."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Make a row of three and another row of three", 2),
    ("Pile red and green. Pile blue and yellow.", 2),
    ("Build a pyramid of three. Build another pyramid of three.", 2),
])
def test_structures_said_one_by_one_are_each_made(text, expected):
    """One row, one pile and one pyramid had been made of two said, silently."""
    schema = check_feasibility(parse(text))
    kinds = [type(p).__name__ for p in schema.goal_predicate().walk() if type(p).__name__ in ("InLine", "Piles", "Pyramid")]
    groups = sum(len(p.groups) or 1 for p in schema.goal_predicate().walk() if type(p).__name__ == "Piles")
    assert (groups if "Piles" in kinds else len(kinds)) == expected


@pytest.mark.parametrize("text, expected", [
    ("heap the cyan and black blocks into one pile", ["pile(black,cyan)"]),
    ("Let's make a rainbow row! Put red, orange, yellow, green and blue in a line from left to right.",
     ["line[left_to_right](red,orange,yellow,green,blue)"]),
    ("place a green block on the red block. place two more green blocks on the green block", ["stack(red,green,green,green)"]),
    ("Put the red and blue cubes both on the blue patch", ["on_patch(blue,red,patch:blue)"]),
])
def test_one_structure_said_twice_or_one_group_on_a_patch_stays_one(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "Put the tower of red and green left of the tower of blue and yellow",
    "Build one tower of red, green and one of blue, yellow",
    "Build a tower using red and green, and another using blue and yellow",
    "Goal: a row of red and green, and blue on yellow",
])
def test_two_towers_read_as_one_or_a_relation_dropped_beside_a_row_are_refused(text):
    """Each had compiled silently wrong (second attack): the towers merged into one, "blue on yellow" made two more cubes
    of the row."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Stack red, green, blue bottom to top. Stack white, black bottom to top.", ["stack(red,green,blue)", "stack(white,black)"]),
    ("Make a row of red and green, and put blue on yellow", ["line(green,red)", "stack(yellow,blue)"]),
    ("put the yellow block on the red and green blocks", ["pyramid(green,red|yellow)"]),
])
def test_towers_commanded_one_by_one_and_a_pair_beside_a_row_are_read_apart(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


def test_a_step_s_then_leaves_its_tower_s_order_free():
    """"Then stack blue and yellow." had ordered blue under yellow (the step's "then" read as the list's order)."""
    schema = check_feasibility(parse("Stack red and green. Then stack blue and yellow."))
    assert sorted(type(p).__name__ for p in schema.goal_predicate().walk()) == ["And", "UnorderedStack", "UnorderedStack"]


@pytest.mark.parametrize("text", [
    "Spell CAT. Spell DOG.",
    "Make two rows of three: red green blue, yellow white black",
    "Make two rows of three, the first red, green, blue and the second white, black, pink",
    "Stack red on green and blue on yellow, both left of white",
    "Stack red on green and blue on yellow, both left of the white patch",
    "Stack red on green and blue on yellow. Put the second tower on the white patch.",
    "Stack red on green and blue on yellow, then put it on the white patch",
])
def test_a_word_a_row_or_a_tower_lost_among_several_is_refused(text):
    """Each had compiled silently wrong (second attack): "Spell CAT." dropped as a title, rows said cube by cube made a
    grid that judges only its shape, "both left of white" related one tower, "the second tower" and "it" moved the first."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("CHALLENGE 2 - Tower Rush. Build a tower of red and blue.", ["stack(red,blue)"]),
    ("Make a 2x3 grid of red, green, blue, white, black and pink cubes", ["grid(2x3:black,blue,green,pink,red,white)"]),
    ("Put red on blue and put it on the green patch", ["on_patch(blue,patch:green)", "stack(blue,red)"]),
])
def test_a_title_a_grid_of_named_cubes_and_it_of_one_tower_stay_read(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "two of the three green cubes on the blue patch",
    "Of the three green cubes, two go on the blue patch.",
    "put all but one of the three red cubes on the blue patch",
    "put all the red cubes but one on the blue patch",
    "put 2-3 red cubes on the blue patch",
    "put two to three red cubes on the patch",
    "put 3 or so red cubes on the blue patch",
    "put red cube * 2 on the blue patch",
    "put -2 red cubes on the blue patch",
    "put the red cube on the blue patch and all other cubes on the green patch",
    "stack 2 cubes: red, blue, green",
    "make a line of 3 cubes: red, blue",
    "put two A blocks on the blue patch",
    "put 3 3 cubes on the blue patch",
])
def test_partitives_ranges_counts_against_lists_and_shared_labels_are_refused(text):
    """Each had compiled silently wrong (third attack): the whole group placed for "two of the three", one number taken
    from a range, every other cube made up, a list padded to its count or cut, a label's cubes made cubes of colours."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Build two towers: one of three red blocks and one of two blue blocks.", ["stack(blue,blue)", "stack(red,red,red)"]),
    ("Sir, please make a circle of cubes - 3 green and 3 yellow - in the middle of the table.",
     ["circle(green,green,green,yellow,yellow,yellow)@center"]),
    ("Make a tower of 3 cubes: red, blue, green.", ["stack(red,blue,green)"]),
    ("Put the B, the A and the T blocks in a row from left to right.", ["line[left_to_right](B,A,T)"]),
    ("Stack the 3 blocks: red, green, blue.", ["stack(red,green,blue)"]),
])
def test_one_of_each_structure_a_list_that_fits_its_count_and_labels_listed_stay_read(text, expected):
    """"the T blocks" after "the B, the A" had dropped the T cube, silently."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "put each of the red cubes on a different patch",
    "put two cubes of each colour on the patch",
    "put one cube of each colour on the blue patch",
    "make a line of red and blue cubes, three of each",
])
def test_own_patches_and_counts_of_each_the_task_cannot_say_are_refused(text):
    """Each had compiled silently wrong (third attack): every cube on one gray patch, one red cube for 'one cube of each
    colour', one of each for 'three of each'."""
    with pytest.raises(ParseError):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Put each cube on its own patch of the same colour.", ["on_patch(blue,patch:blue)", "on_patch(red,patch:red)"]),
    ("Make two separate piles, one of the orange blocks and one of the cyan blocks. There are two of each.",
     ["piles(cyan,cyan,orange,orange;by=color)"]),
    ("Build two towers of each three cubes: one only red, one only blue.", ["stack(blue,blue,blue)", "stack(red,red,red)"]),
])
def test_a_patch_of_its_colour_and_counts_of_each_said_stay_read(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    ("Build a tower with the 4 cube at the bottom and the 2 cube on top of it.", ["stack(4,2)"]),
    ("Build a tower with the 5 cube at the bottom and the 3 cube above it.", ["stack(5,3)"]),
    # it had made up a red cube under the digit 1 cube, then was refused; the tower is the digits listed
    ("build a tower of digit blocks from bottom to top: the digit 1 block, the digit 2 block.", ["stack(1,2)"]),
])
def test_a_digit_cube_s_label_is_no_count_of_the_tower(text, expected):
    """The bottom cube's digit had been read as the tower's height too, and the tower filled with cubes nobody named
    (stack(4,2,red,blue)), silently: the class of stranger48's silent error, reported by a helper with its own example."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, dropped", [
    ("Put the red cube on the blue cube. Check your air gauge.", True),
    ("Put the red cube on the blue cube. Wash your hands.", True),
    ("Put the red cube on the blue cube. Check your tower.", False),
    ("Put the red cube on the blue cube. Move your arm back.", False),
    ("Put the red cube on the blue cube. Don't touch your face.", False),
])
def test_an_imperative_on_a_person_s_own_thing_is_their_world(text, dropped):
    """A voice's imperative on a thing of a person's own ("Check your air gauge.") is set aside, listed as such; one on a
    thing of the task or the robot stays and is refused."""
    if dropped:
        assert meaning(check_feasibility(parse(text))) == ["stack(blue,red)"]
    else:
        with pytest.raises(ParseError):
            check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    "Make a tower red green and a tower blue yellow, bottom to top",
    "Make a tower of red and green and a tower of blue and yellow, both from bottom to top.",
])
def test_a_direction_said_once_after_two_towers_orders_both(text):
    """The first tower had been left unordered, silently (the second attack)."""
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == ["stack(blue,yellow)", "stack(red,green)"]
    assert [type(p).__name__ for p in schema.goal_predicate().walk()][1:] == ["Stack", "Stack"]


@pytest.mark.parametrize("text, expected", [
    ("Build two towers of two cubes, one on the white patch and one on the black patch",
     ["on_patch(red,patch:black)", "on_patch(red,patch:white)", "stack(red,red)", "stack(red,red)"]),
    ("Stack the red blocks on the red patch and the blue blocks on the blue patch",
     ["on_patch(blue,patch:blue)", "on_patch(red,patch:red)", "stack(blue,blue)", "stack(red,red)"]),
])
def test_towers_on_patches_named_by_colour_keep_their_cubes_colours_free(text, expected):
    """The towers' cubes had been made white and black, like their patches, a colour no word gave them (an attack's
    class); cubes named by colour keep theirs."""
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # each tower's cubes said "made only of": the colours had been spread over both towers (stack(red,blue) twice)
    ("Two towers, two cubes each: one made only of red cubes and one made only of blue cubes.",
     ["stack(blue,blue)", "stack(red,red)"]),
    # a heading counting towers, then each tower as a chain with its place (refused: "which cubes make each tower")
    ("Build two towers of two cubes: yellow on orange in the back left corner, and white on gray in the front right corner.",
     ["stack(gray,white)@front_right", "stack(orange,yellow)@back_left"]),
    ("We want two separate towers at the end: pink on purple, and black on white.",
     ["stack(purple,pink)", "stack(white,black)"]),
    # label cubes named by the plural noun first (two coloured cubes had been made up, or refused)
    ("Put digit cubes 3 and 4 next to each other.", ["next_to(3,4)"]),
    ("Put cubes 3 and 4 next to each other.", ["next_to(3,4)"]),
    # the label noun before them keeps its own reading (it had become "letter the letter H cube ...": H under I)
    ("Stack the letter cubes H and I with H on top of I.", ["stack(I,H)"]),
    # the middle said by "above it" between the tower's ends (read X, Z, Y and refused for a made-up cube)
    ("Stack the letter cubes with X at the bottom, Y above it and Z on top.", ["stack(X,Y,Z)"]),
    # an identifier of words alone before the colon ("could not parse 'variant'", "'script' is an action")
    ("Demo-day row: black on the far left, red in the middle, cyan on the far right.", ["line[left_to_right](black,red,cyan)"]),
    ("Data-collection script, line 12: put the green cube in the front left corner.", ["in_region(green,front_left)"]),
    ("TOWER 3: base brown, mid orange, top cyan", ["stack(brown,orange,cyan)"]),
])
def test_stranger49_towers_label_cubes_and_identifiers_are_read(text, expected):
    """stranger49's refusals and its one silent error (read after its transfer figure was recorded), each with its
    meaning; the place of a task after an identifier is cited (it had been reported as demanded by no word)."""
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert not uncited(schema)


@pytest.mark.parametrize("text, anchored", [
    ("Tower variant B: the gray block must be the bottom one, and the blue and yellow blocks go above it in either order.",
     "AnchoredStack(objects=['gray', 'blue', 'yellow'], bottom=True)"),
    # the free cubes said again after the tower's list: two more cubes had been made (a tower of five)
    ("Build a tower of gray, blue and yellow with gray at the bottom; blue and yellow in any order.",
     "AnchoredStack(objects=['gray', 'blue', 'yellow'], bottom=True)"),
    ("Build a tower: red on top, and blue and green below it in any order.",
     "AnchoredStack(objects=['blue', 'green', 'red'], top=True)"),
])
def test_a_tower_s_named_end_and_the_others_in_any_order(text, anchored):
    """A tower with one end named and the others said free keeps only that end."""
    parts = [p for p in check_feasibility(parse(text)).goal_predicate().walk() if type(p).__name__ != "And"]
    assert [repr(p) for p in parts] == [anchored]


@pytest.mark.parametrize("text", [
    "Two towers of two cubes: the red cubes in one, the blue cubes in the other.",
])
def test_each_tower_s_cubes_said_in_words_not_read_are_refused(text):
    """Towers whose cubes are said one tower at a time in words the reader does not take apart are refused (the colours
    had been spread over every tower)."""
    with pytest.raises(ParseError, match="each tower"):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a start under a heading, "take off the X", "a tower with X on Y", "a two-block tower, X under Y"
    ("Starting scene: blue on top of red. Take off the blue cube and put it on the yellow patch.",
     ["on_patch(blue,patch:yellow)", "start:stack(red,blue)"]),
    ("There's a two-block tower, orange under cyan. Add a pink block on top of it.",
     ["stack(orange,cyan,pink)", "start:stack(orange,cyan)"]),
    ("Starting from a tower with yellow on blue, take the yellow cube off and put it on the table.",
     ["on_table(yellow)", "start:stack(blue,yellow)"]),
    # the direction a list is said in, a line across a part of the table
    ("A tower of yellow, then green, then blue, counted from the bottom.", ["stack(yellow,green,blue)"]),
    ("Lay out a row of three that goes blue, gray, pink when you read it from right to left.",
     ["line[right_to_left](blue,gray,pink)"]),
    ("Arrange the three white cubes in a line across the middle of the table.", ["line(white,white,white)@center"]),
])
def test_stranger49_starts_and_directions_are_read(text, expected):
    """stranger49's refusals over a start's or a direction's wording ('scene', 'counted', 'across', 'when'); every
    constraint cited (the tower's order had been reported as demanded by no word)."""
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected
    assert not uncited(schema)


@pytest.mark.parametrize("text, expected", [
    ("While the glaze sets, put the blue cube on the red cube and the red cube on the yellow cube.", ["stack(yellow,red,blue)"]),
    ("The spaniel's vaccinations are done. While I write up the chart, put the brown cube on the gray patch, please.",
     ["on_patch(brown,patch:gray)"]),
    ("Before lunch, put red on blue.", ["stack(blue,red)"]),
])
def test_a_clause_of_the_speaker_s_time_is_set_aside(text, expected):
    """A clause of time that names nothing of the task ("While the glaze sets,") times nothing a goal holds (it had been
    refused as a time); it is listed as set aside."""
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == expected


@pytest.mark.parametrize("text", [
    "While the red cube is on the blue cube, put green on top.",  # the task's cube
    "Put red on blue while the timer runs.",  # a measure of time
    "Until the bell rings, put red on blue.",  # a duration
    "After it falls, put red on blue.",  # a reference
    "While the robot waits, put red on blue.",  # the robot
])
def test_a_clause_of_time_about_the_task_stays_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a cube listed, then said to be the bottom one, and the top one: the same cubes (two more had been made up)
    ("Stack red, blue and green. Red must be the bottom one and green should be the top one.", ["stack(red,blue,green)"]),
])
def test_a_listed_tower_s_ends_said_again_keep_its_cubes(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    # a hostile helper's attack on this session's readings (each had compiled to another task)
    "Stack red cubes A and B.",  # a coloured cube had been made up
    "Put blocks 3 and 4 on the red patch.",  # two coloured cubes had been made up for the labels
    "Build a tower of five cubes with red at the bottom, blue above it and then green and yellow and white on top.",
    "Two-tower variant: red on blue.",  # a count in the label had been dropped (one tower)
    "Baseline, 3 towers: red on blue.",
    "Stack red, blue and green with blue second, counted from the top.",  # cubes had been made up
    "Two towers of different heights: one made only of red cubes and one made only of blue cubes.",
    # older classes the attack found: one tower's colour said of two (the other had been made red too); a listed tower
    # that refers to another ("white on top of it": red and blue had been made up for "it")
    "Two towers, two cubes each: one made only of red cubes.",
    "Build two towers: yellow on orange, and white on top of it.",
])
def test_this_session_s_readings_refuse_what_they_cannot_say(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # the thirty-eighth session, from stranger50 (read after its figures) and variants of it
    ("From the glassblower's chair: cube A at the bottom of a tower, cube M on it, and cube Z on top.", ["stack(A,M,Z)"]),  # (A,Z,M)
    ("the red cube at the bottom of a tower, the blue cube on it, and the green cube on top.", ["stack(red,blue,green)"]),
    ("Make a tower: blocks A and B, with A on top.", ["stack(B,A)"]),  # blocks A and B: the letter cubes
    ("Sanity check task: one tower out of cubes A and B, order free.", ["stack(A,B)"]),
    ("Make a two-cube tower from the orange and purple cubes; whichever ends up on top is fine.", ["stack(orange,purple)"]),
    ("Tower of green, white and red, with red on top. The other two can go either way.", ["stack(green,white,red)"]),
    ("Stack the letter cubes so that Q is on top of P and R is on top of Q.", ["stack(P,Q,R)"]),
    ("Make a stack in which the white cube is on top, the gray cube is just below it and the black cube is at the base.",
     ["stack(black,gray,white)"]),
    ("The cyan cube goes on the bottom, with the two brown cubes stacked above it.", ["stack(cyan,brown,brown)"]),
    ("The yellow cube must be at the bottom; put the cyan and the pink cubes on it in whatever order.", ["stack(yellow,cyan,pink)"]),
    ("Given a two-cube tower of orange under gray, add the cyan cube on top.", ["stack(orange,gray,cyan)", "start:stack(orange,gray)"]),
    ("Scene before: purple cube stacked on the brown cube. Scene after: the purple cube sitting to the right of the brown cube.",
     ["right_of(purple,brown)", "start:stack(brown,purple)"]),
    ("Instruction for the next rollout: collect the pink and green cubes into one pile.", ["pile(green,pink)"]),
    ("Replay buffer label: place cube K on the orange patch.", ["on_patch(K,patch:orange)"]),
    ("Stack all three of them, black, gray and brown. Any order will do as long as they end up in a single tower.",
     ["stack(black,gray,brown)"]),
    ("The black cube should finish near the back edge of the table.", ["in_region(black,back)"]),
    ("Lay out the orange, white and pink cubes side by side, orange on the left end and pink on the right end.",
     ["line[left_to_right](orange,white,pink)"]),
    ("Episode succeeds when the black cube is touching the white cube, side by side.", ["next_to(black,white)"]),
    ("Starting from a stack of blue, yellow, pink (bottom to top), unstack everything onto the table.",
     ["on_table(blue)", "on_table(pink)", "on_table(yellow)", "start:stack(blue,yellow,pink)"]),
    ("Build two towers, one in the front right corner with cyan on top of brown, and one in the back left corner with gray on "
     "top of red.", ["stack(brown,cyan)@front_right", "stack(red,gray)@back_left"]),
    ("The red cube should end up diagonally behind the yellow cube, off to its right.", ["behind(red,yellow)", "right_of(red,yellow)"]),
    ("A good rind takes patience, and so does this: stack the brown, cyan and orange cubes into one tower in whatever order suits "
     "you.", ["stack(brown,cyan,orange)"]),
    ("The spec asks for the red cube to be placed on the blue patch.", ["on_patch(red,patch:blue)"]),
    ("Make a loose heap of the red, yellow and cyan cubes.", ["pile(cyan,red,yellow)"]),
])
def test_thirty_eighth_session_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Tower of green, white, blue and red, with red on top. The other two can go either way.",  # two others of three: not said
    "Put blocks A and 4 on the red patch.",  # a letter and a digit: which cubes is not said
    "Put the red cube diagonally behind the blue cube.",  # on which side: not said
    # "one more" of a colour: of none said before (a whole edit read as a task had become green under red), or one more
    # than the one said (dropped: a tower of two)
    "one more green under the red",
    "Stack all four of them, black, gray and brown.",  # the count and the list differ (a tower of three had been read)
    "Stack all three of them: black, gray, brown and white.",  # (a tower of four)
    "The yellow cube must be on top; put the cyan and the pink cubes on it in whatever order.",  # on the top cube?
    "stack the green cube on the red cube, then one more green on top",
    "Stack a blue cube on a red cube, then one more blue cube on top.",
])
def test_thirty_eighth_session_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


def test_a_count_before_a_heading_is_no_identifier_label():
    # "Tower of 3." ends like an identifier ("Trial 12.") but counts the tower's cubes (the words joining an identifier's,
    # "for the next", had let it be dropped: a tower of two)
    atoms = meaning(check_feasibility(parse("Tower of 3. Base: gray. Top: yellow.")))
    assert len(atoms) == 1 and atoms[0].startswith("stack(gray,") and atoms[0].endswith(",yellow)") and atoms[0].count(",") == 2


@pytest.mark.parametrize("text, expected", [
    # stranger51 (read at the thirty-ninth session's start): words said to someone else before a turn to the robot or the
    # cubes (they had been refused as actions, counts or times)
    ("Take one capsule twice daily with food. And for the robot: put both red cubes on the white patch.",
     ["on_patch(red,red,patch:white)"]),
    ("One more pint for the regular at the end - and for the robot, the red cube on the black cube.", ["stack(black,red)"]),
    ("Nurse, keep the field sterile. Robot, place the red cube in the front left corner.", ["in_region(red,front_left)"]),
    ("Dosage double-checked, 500 milligrams, all good. Now the cubes: the blue one to the left of the orange one.",
     ["left_of(blue,orange)"]),
    # a placement said with its place first (no task had been found)
    ("Between the two black cubes goes the orange cube.", ["between(orange;black,black)"]),
    ("On top of the blue cube goes the red cube.", ["stack(blue,red)"]),
    # cubes listed as the subject of one bare side: the table's side (it had been read as relative to the first cube)
    ("The white cube and the black cube both go to the right side.", ["in_region(black,right)", "in_region(white,right)"]),
    ("Build a tower from two orange cubes and one purple cube. Order is up to the policy.", ["stack(orange,orange,purple)"]),
    # digit labels said again with a place: those cubes (the digit had been read as a count: a tower of four cubes of
    # default colours, or a cube made up in the middle; silently wrong)
    ("Stack the cubes labelled 4 and 2 with 4 at the bottom.", ["stack(4,2)"]),
    ("Stack the cubes labelled 4, 7 and 2 with 4 at the bottom and 2 on top.", ["stack(4,7,2)"]),
    ("Stack the cubes numbered 4 and 2 with 4 at the bottom.", ["stack(4,2)"]),
    ("Put the cubes numbered 4 and 2 on the red patch.", ["on_patch(2,4,patch:red)"]),
    ("Put the red cube between the cubes labelled 4 and 6.", ["between(red;4,6)"]),
])
def test_thirty_ninth_session_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Make it quick. Robot, put the red cube on the blue cube.",  # a manner that may be the robot's: not dropped
    "Stack twice. And for the robot: put both red cubes on the white patch.",  # a goal word before the turn
    "Ignore the rest. Robot, place the red cube in the front left corner.",  # a take-back
    "Don't touch anything. Robot, put the red cube on the blue cube.",  # a negation
    "Put the red cube on the blue cube and the green cube on the left.",  # the green cube's own clause: relative
])
def test_thirty_ninth_session_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("pre", [
    # a hostile helper's preambles before a turn to the robot (the first version of the rule had dropped them all)
    "Upside down.", "Swap.", "Twice.", "Three of each.", "Four in total. Okay", "Spell CAT.", "Make the word DOG.", "Centered.",
    "On the shelf.", "Like yesterday.", "As shown earlier.", "Oops.", "Make a tawer.", "Inverted.", "Vice versa.",
    "Alphabetical order.", "Evenly spaced.", "Make the whole thing three times bigger for the big display.",
    "Put everything on the shelf first, nurse.",
])
def test_words_before_a_turn_to_the_robot_that_may_change_the_task_are_not_dropped(pre):
    text = f"{pre} Robot, put the red cube on the blue cube."
    try:
        atoms = meaning(check_feasibility(parse(text)))
    except BadInput:
        return
    assert atoms != ["stack(blue,red)"], text  # read as if the words before had not been said


@pytest.mark.parametrize("text", [
    # a relation after the cube of a placement said place first belongs to that cube: not read that way, refused
    "Left of the red cube goes the blue cube on the green cube.",
    "Behind the red cube goes the blue cube in front of the green cube.",
    # cubes listed before a bare side after another sentence: the side may be the tower's
    "Make a tower of the red cube and the blue cube. The green cube and the yellow cube go on the right.",
])
def test_thirty_ninth_session_attack_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    # a second hostile helper's preambles (conditions, a distance, copies, a size, a repetition, a time before the turn)
    "If the toddler wakes, meanwhile, put the red cube on the blue cube.",
    "Until the kettle boils, in the meantime, put the red cube on the blue cube.",
    "Allow 10 cm spacing, folks. Robot, put the red cube left of the blue cube.",
    "Three duplicates please, folks. Robot, put the red cube on the blue cube.",
    "Use the jumbo pieces, folks. Robot, put the red cube on the blue cube.",
    "Perform the routine twice daily. Robot, put the red cube on the blue cube.",
    "Pause ten mins beforehand, folks. Meanwhile, put the red cube on the blue cube.",
    "Stack red on blue, then red again.",  # "again" with one "then": not a list (stays refused)
])
def test_thirty_ninth_session_second_attack_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("A tower: cyan at the bottom, then red, then cyan again.", ["stack(cyan,red,cyan)"]),
    ("Reward fires when the pink cube is resting on top of the brown cube.", ["stack(brown,pink)"]),
    ("Your new frames come in on Thursday. In the meantime, stack the three yellow cubes.", ["stack(yellow,yellow,yellow)"]),
    ("Closing the incision, three sutures. Meanwhile the yellow cube goes on the blue patch.", ["on_patch(yellow,patch:blue)"]),
])
def test_thirty_ninth_session_later_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # the fortieth session's readings (stranger52, read): a fronted place, a relative clause of colour, a side "along"
    # the table, a colour list given a direction, a tower said from its bottom cube by cube, "next to both", a report
    ("Between the brown cube and the pink cube, put the white cube.", ["between(white;brown,pink)"]),
    ("On top of the blue cube, place the red one.", ["stack(blue,red)"]),
    ("The cube that is red should be placed in front of the cube that is black.", ["in_front_of(red,black)"]),
    ("Arrange four cubes in a line along the front of the table: red, red, blue, blue, left to right.",
     ["line[left_to_right](red,red,blue,blue)@front"]),
    ("Lay the cubes out red, orange, yellow, green from left to right along the back of the table.",
     ["line[left_to_right](red,orange,yellow,green)@back"]),
    ("Lay out red, orange and yellow, left to right.", ["line[left_to_right](red,orange,yellow)"]),
    ("The bottom cube should be grey, the second one black, the third one white and the top one red.",
     ["stack(gray,black,white,red)"]),
    ("Build a tower. The bottom cube should be grey, the second one black and the top one red.", ["stack(gray,black,red)"]),
    ("Build a tower of four cubes. The bottom one is black and the top one is yellow; the two in between are both blue.",
     ["stack(black,blue,blue,yellow)"]),
    ("Put the pink cube next to both the orange cube and the purple cube.", ["next_to(orange,pink)", "next_to(pink,purple)"]),
    ("He told me the A cube goes to the left of the B cube.", ["left_of(A,B)"]),
    ("My supervisor said the white cube should go on top of the black cube.", ["stack(black,white)"]),
    ("The professor told us to put the white cube on the black cube.", ["stack(black,white)"]),
])
def test_fortieth_session_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "A tower of the X and Y blocks, either one on top.",
    "Build a tower of the X block and the Y block in any order.",
])
def test_a_tower_of_two_label_cubes_in_any_order_demands_no_order(text):
    from rpg.domain.predicates import UnorderedStack

    goal = check_feasibility(parse(text)).goal_predicate()
    assert any(type(p) is UnorderedStack for p in goal.walk()), text


@pytest.mark.parametrize("text", [
    # a report taken back or weighed after it, and a correction with "but actually": refused, not read as both
    "He said the red cube should go on the blue cube, but actually put it on the green one.",
    "Put the red cube on the blue cube, but actually put it on the green one.",
    "Stack red on blue, but actually I want it next to the green one.",
    "She told me not to put the red cube on the blue cube.",
    "He said the red cube is on the blue cube.",
    # a tower said from its bottom with a gap in its ordinals, or beside another structure
    "The bottom cube should be grey, the third one black and the top one red.",
    "Build two towers. The bottom cube should be grey, the second one black and the top one red.",
    "Make a row of three. The bottom cube should be grey, the second one black and the top one red.",
    "Build a tower of four cubes. The bottom cube is grey, the second one black and the top one red.",
    "Between the brown cube and the pink cube, don't put the white cube.",
])
def test_fortieth_session_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a hostile helper's silent classes (fortieth session), now read as said
    ("Put red on blue and make a row of green and yellow.", ["line(green,yellow)", "stack(blue,red)"]),
    ("Put red on blue and line up green and yellow.", ["line(green,yellow)", "stack(blue,red)"]),
    ("Put red next to blue and make a row of green and yellow.", ["line(green,yellow)", "next_to(blue,red)"]),
    ("Put red left of blue and make a tower of green and yellow.", ["left_of(red,blue)", "stack(green,yellow)"]),
    ("Put red between blue and green and between yellow and pink.", ["between(red;blue,green)", "between(red;pink,yellow)"]),
    ("Put the black cube between the red cube and the yellow patch.", ["between(black;patch:yellow,red)"]),
    ("Put red to the left of blue, correction, to the right.", ["right_of(red,blue)"]),
    ("Stack three, I mean four, red cubes.", ["stack(red,red,red,red)"]),
    ("Put two — I mean three — red cubes on the green patch.", ["on_patch(red,red,red,patch:green)"]),
    ("Put the red cube left of the blue cube, both in the front left corner.",
     ["in_region(blue,front_left)", "in_region(red,front_left)", "left_of(red,blue)"]),
    ("Put a red cube on the blue patch and another red cube on the green patch.",
     ["on_patch(red,patch:blue)", "on_patch(red,patch:green)"]),
])
def test_fortieth_session_attack_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # a hostile helper's silent classes (fortieth session), refused: a second structure that took the first's cubes, a
    # place said of "both"/"all" held of one, one colour at both ends of a tower, "another red" dropped, a between lost
    # in a row, a contrast ("instead of on green"), a list corrected in its middle
    "Put red on blue and make a row of red and yellow.",
    "Put red on blue and then make a row of green and yellow next to it.",
    "Put red on blue and make a row of them.",
    "Put red on the left and blue on the right, both at the back.",
    "Put red on the green patch and blue on the yellow patch, both at the front.",
    "Put red and green on the white patch, both next to blue.",
    "Put red between blue and green, all at the back.",
    "Put red in front of blue and green behind blue, all in the center.",
    "Make a tower of three cubes, red at the top and bottom and blue in the middle.",
    "Make a tower of three cubes with red at the top and the bottom.",
    "Make a tower of three cubes with red at the bottom and on top.",
    "Stack red on blue, and another red on top.",
    "Stack red on blue and a second red on top.",
    "Put red on blue and another red next to blue.",
    "Make a row with red between blue and green.",
    "Put red between blue and green, in a row.",
    "Put red on blue instead of on green.",
    "Put red next to blue rather than next to green.",
    "Put red left of blue, instead of right of green.",
    "Put red between blue and green, instead of between yellow and pink.",
    "Line up red, blue, sorry, green, and yellow from left to right.",
])
def test_fortieth_session_attack_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Place the orange cube on the purple-coloured patch.", ["on_patch(orange,patch:purple)"]),
    ("Put the orange cube on the purple colored patch.", ["on_patch(orange,patch:purple)"]),
    ("Make a row of red, green and blue from left to right: blue is third from the left.",
     ["line[left_to_right](red,green,blue)"]),
    ("Make a tower from bottom to top of red, green, blue, with blue on top.", ["stack(red,green,blue)"]),
])
def test_fortieth_session_second_attack_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # an approximate or added count, a rank the reading dropped or a cube it made for it, a list against its own end, a
    # spelled word dropped beside a relation (a hostile helper's silent classes, fortieth session)
    "Make a tower of three or so red cubes.",
    "Stack three red cubes, plus one.",
    "Make a row of red, green and blue: red is third from the left.",
    "Make a row of red, green and blue, red is second.",
    "Build a tower of red, blue and green in which red is higher than blue.",
    "Stack red, blue and green, red over blue.",
    "Build a tower of red, blue, green: red is second from the bottom.",
    "Build a tower of red, blue, green, yellow: red at the bottom, yellow second.",
    "Make a tower from bottom to top of red, green, blue, with green on top.",
    "Spell GO, then put the red cube next to the G.",
    "Spell UP, then put the red cube on the P.",
])
def test_fortieth_session_second_attack_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Put red to the right of blue and green to the right of yellow, sorry, to the left.",
     ["left_of(green,yellow)", "right_of(red,blue)"]),
    ("Put the red cube on the blue cube. Put the green and yellow cubes in a row on the left.",
     ["line(green,yellow)@left", "stack(blue,red)"]),
    ("Put red on blue and put green and yellow in a row to the left.", ["line(green,yellow)@left", "stack(blue,red)"]),
    ("Build a tower of red, then blue, then red, bottom to top", ["stack(red,blue,red)"]),
    ("Goal: one tower. Gray goes first, then brown on the gray, then cyan on the brown.", ["stack(gray,brown,cyan)"]),
])
def test_fortieth_session_third_attack_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # a second hostile helper's attack on this session's own rules: each had compiled silently wrong
    "Put red next to both blue and green on the yellow patch.",
    "Put red next to both blue and green, in a row.",
    "Build a tower of red, blue and green; green is third.",
    "Build a tower of red, blue and green; red is first.",
    "Put the cube that is orange red on the blue cube.",
    "Put the red and blue coloured cube on the green cube.",
    "Put the red coloured blue cube on the green cube.",
    "Put red to the left of blue and green in front of yellow, sorry, to the right.",
    "The bottom cube is red, the second one blue, the top one green. Put the yellow cube on top.",
    "Make a row with red at the top and bottom.",
    "Put red at the top and bottom of the table.",
    "Move along the back of the table and put red on blue.",
    "Put red, blue and green from left to right, two of them at the back.",
])
def test_fortieth_session_third_attack_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", ["Put red and yellow on blue.", "Stack red and green on top of blue."])
def test_two_bare_colours_on_a_third_leave_the_top_two_free(text):
    from rpg.domain.predicates import AnchoredStack

    goal = check_feasibility(parse(text)).goal_predicate()
    assert any(type(p) is AnchoredStack and p.bottom and not p.top for p in goal.walk()), text


@pytest.mark.parametrize("text, expected", [
    # the forty-first session (stranger53, read): "stacked" is a tower as "a stack" is (a reading of the letters as a row
    # had dropped the word, silently)
    ("I'd like the letters P and T stacked; I don't mind which one ends up on top.", ["stack(P,T)"]),
    ("I'd like the letters P and T stacked in any order.", ["stack(P,T)"]),
    ("The red cube is stacked on the blue cube.", ["stack(blue,red)"]),
    ("Use the stacking blocks red and blue to make a row.", ["line(blue,red)"]),
])
def test_forty_first_session_stacked_is_a_tower(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_a_line_of_three_from_either_end_matches_its_middle_between_the_other_two():
    said = meaning(check_feasibility(parse("Put red, white and blue in a row with white in the middle.")))
    assert matches("line[sequence](red,white,blue)", said) and matches("line[sequence](blue,white,red)", said)
    assert matches("between(white;red,blue); line(red,white,blue)", said)
    assert not matches("line[sequence](white,red,blue)", said)  # red in the middle: another goal
    assert not matches("line[sequence](red,white,blue)@back", said)  # a place the goal does not have


@pytest.mark.parametrize("text, expected", [
    # a wall's rows counted each with its width said (the first row's count had been read as the wall's), and a layer
    # said by its place from the table (it had been dropped: the layers above the bottom were free)
    ("Build a wall 3 wide and 3 high: three red cubes in the bottom row, three yellow cubes in the second row and three blue "
     "cubes in the top row.", ["wall(red,red,red|yellow,yellow,yellow|blue,blue,blue)"]),
    ("Make a 1x3x3 cube of red, yellow and blue blocks with 3 red blocks at the bottom, 3 yellow blocks second from the bottom "
     "and 3 blue blocks third from the bottom.", ["wall(red,red,red|yellow,yellow,yellow|blue,blue,blue)"]),
])
def test_forty_first_session_layers_read_as_said(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # counted runs of one colour said in order (each run had been read as one cube), cubes counted then listed in brackets,
    # a second structure said "a separate pile of" (steer_stranger24's bases, read at the forty-first session)
    ("Put six cubes in a row, three blue and then three white, from left to right.",
     ["line[left_to_right](blue,blue,blue,white,white,white)"]),
    ("Make a row of three blue cubes followed by three white cubes, from left to right.",
     ["line[left_to_right](blue,blue,blue,white,white,white)"]),
    ("Build a pyramid with a bottom row of three cubes (red, green and blue), two yellow cubes on them and a white cube on top.",
     ["pyramid(blue,green,red|yellow,yellow|white)"]),
    ("make a pile of two red cubes and a separate pile of two yellow cubes", ["pile(red,red)", "pile(yellow,yellow)"]),
])
def test_forty_first_session_counted_runs_and_lists(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Make a row of four cubes (red, green and blue).",  # a fourth cube had been made up
    "Build a tower of three blue cubes and then three white cubes on top.",
])
def test_forty_first_session_counts_that_do_not_fit_are_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # stranger53 (read at the forty-first session): the episode's end said ("when you're done"), leave asked ("if that's ok"),
    # "objective"/"aim" for the goal, "one on the other", a counted alternation without "cubes"
    ("Every pink cube should be in the front left corner when you're done.", ["in_region(pink,front_left)"]),
    ("I need a three-block tower with white at the base, black in the middle and gray on top, if that's ok.",
     ["stack(white,black,gray)"]),
    ("The objective is a tower of orange, then white, then green (bottom to top), standing in the centre of the table.",
     ["stack(orange,white,green)@center"]),
    ("put the yellow and orange cubes one on the other, whichever way round", ["stack(yellow,orange)"]),
    ("tower of 5 alternating yellow and green, starting with yellow on the table", ["stack(yellow,green,yellow,green,yellow)"]),
])
def test_forty_first_session_stranger53_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "When you're done, put red on blue.",  # done with what: a condition on something else
    "Put red on blue if that's ok with the blue cube.",
])
def test_forty_first_session_conditions_still_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


def test_a_row_under_a_cube_is_refused():
    """"put a row of green cubes under the red cube" had been a row of the two cubes (the relation and the plural dropped)."""
    with pytest.raises(BadInput):
        check_feasibility(parse("put a row of green cubes under the red cube"))


@pytest.mark.parametrize("text, expected", [
    # stranger54's one silent text (read at the forty-second session): ordinals written with digits ("2nd=gray") had been
    # split into a count and an unknown word, and the tower's middle dropped
    ("tower pls: bottom=pink, 2nd=gray, 3rd=cyan, top=red", ["stack(pink,gray,cyan,red)"]),
    # steer_stranger25's bases (read at the forty-second session): who orders the task, finding cubes on the way to placing
    # them, a row "across" a side of the table, "Anyway," before the task, a heading that counts rows
    ("The court orders that the blue cube be placed on top of the green cube.", ["stack(green,blue)"]),
    ("The court orders the orange cube placed between the pink cube and the purple cube.", ["between(orange;pink,purple)"]),
    ("The client requests a row of three red cubes.", ["line(red,red,red)"]),
    ("Everybody find the letter blocks C, A and T and spell CAT from left to right.",
     ["line[left_to_right](C,A,T)", "reads(C,A,T;direction=left_to_right,face=up,text=CAT)"]),
    ("Locate the red cube, then stack it on the blue cube.", ["stack(blue,red)"]),
    ("Set a line of five white cubes across the back of the table.", ["line(white,white,white,white,white)@back"]),
    ("Line up three red cubes across the front.", ["line(red,red,red)@front"]),
    ("Anyway, pop the yellow cube on the green patch.", ["on_patch(yellow,patch:green)"]),
    ("Let's make two rows, friends: a row of three red blocks and a row of three blue blocks.",
     ["line(blue,blue,blue)", "line(red,red,red)"]),
    # a layer said above the one before it (the cubes "above those" had been read in the second layer, and the second's
    # cubes split between layers: silently wrong before this session), and a two-row wall said below and above
    ("Build a pyramid with three white cubes on the bottom row, two white cubes above them and one white cube at the peak.",
     ["pyramid(white,white,white|white,white|white)"]),
    ("Build a pyramid: three red cubes on the bottom row, two blue cubes above them and one green cube above those.",
     ["pyramid(red,red,red|blue,blue|green)"]),
    ("Build a pyramid: three red cubes on the bottom row, two blue cubes on them and one green cube on top of those.",
     ["pyramid(red,red,red|blue,blue|green)"]),
    ("Build a two-row wall along the front: three blue cubes below, three green cubes above.",
     ["wall(blue,blue,blue|green,green,green)@front"]),
    # a cube "with" another on top of it (no verb had been found), and a heading naming in a voice what its colon's text
    # builds (its nouns had been refused as objects the domain lacks)
    ("A purple cube with a pink cube on top of it.", ["stack(purple,pink)"]),
    ("The purple cube with the pink cube under it.", ["stack(pink,purple)"]),
    ("Plate it: put the red cube on the blue patch and the yellow cube on the green patch.",
     ["on_patch(red,patch:blue)", "on_patch(yellow,patch:green)"]),
    ("Let's make a little train: four blocks in a row, red, blue, red, blue, from left to right.",
     ["line[left_to_right](red,blue,red,blue)"]),
    ("Yellow cube, proceed to the back right corner.", ["in_region(yellow,back_right)"]),  # 'proceed' is 'go'
    # a verb the lexicon lacks in the caused-motion construction, verb + cube + where it goes, moves the cube there
    ("Ground to robot: taxi the yellow cube to the back left corner of the table.", ["in_region(yellow,back_left)"]),
    ("Post the red cube to the front right corner of the table.", ["in_region(red,front_right)"]),
    ("Park the brown cube behind the gray cube.", ["behind(brown,gray)"]),
    # stranger54's rows (read): three places said without colons, a row of two with a side relation of its cubes, one cube
    # at an end and the other four
    ("row: far left brown, middle gray, far right green", ["line[left_to_right](brown,gray,green)"]),
    ("Please to arrange red and blue cubes in a row, red at left of blue.", ["line[left_to_right](red,blue)"]),
    ("Arrange the red and blue cubes in a row with blue to the right of red.", ["line[left_to_right](red,blue)"]),
    ("Make a row of five cubes: a pink one at the far left, the other four gray.", ["line[left_to_right](pink,gray,gray,gray,gray)"]),
])
def test_forty_second_session_more_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, end, fixed, free", [
    # one end of a tower of three fixed, the other two "in either order" (read as a contradiction before): a stack anchored
    # at that end, the two others free
    ("Tower of three: blue on top; the other two, red and white, can go in either order.", "top", "blue", {"red", "white"}),
    ("Tower of three: blue at the bottom, the other two red and green in any order.", "bottom", "blue", {"red", "green"}),
])
def test_forty_second_session_tower_with_one_end_fixed(text, end, fixed, free):
    from rpg.domain.predicates import AnchoredStack

    goal = check_feasibility(parse(text)).goal_predicate()
    assert isinstance(goal, AnchoredStack) and getattr(goal, end) and not getattr(goal, {"top": "bottom", "bottom": "top"}[end])
    ends = goal.objects[-1] if end == "top" else goal.objects[0]
    assert ends == fixed and set(goal.objects) - {fixed} == free


@pytest.mark.parametrize("text, expected", [
    ("Build a tower of red, white and blue with blue on top.", ["stack(red,white,blue)"]),
    # a test's name is no schedule (only "every"/"each" with a time of day, day or session is one)
    ("Nightly regression #41: the cyan cube ends in the front right corner.", ["in_region(cyan,front_right)"]),
    ("Build a tower where the first (lowest) cube is green, the second is orange and the third is purple.",
     ["stack(green,orange,purple)"]),
])
def test_forty_second_session_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Every morning, line up three yellow cubes.",  # a schedule (stranger54: 'morning' had been dropped as a filler)
    "Line up three yellow cubes every day.",
    "Put the red cube on the blue patch each session.",
    "Find the red cube.",  # finding alone places nothing
    "Make two rows: a row of three red blocks.",  # the heading counts a row nobody described
    "tower: bottom=pink, c2=gray, top=red",  # a cube between the roles with no place among them
    "Make a row of five cubes: a pink one at the far left, the other three gray.",  # the counts do not add up
    "row: far left brown, middle gray",  # two of three places
    "Melt the red cube on the blue patch.",  # a change of the cube, not only where it ends
    "Hurl the red cube onto the blue patch.",  # a throw
    "Glue the red cube to the blue cube.",
    # headings a hostile helper found dropped: a thing known by its order or shape, someone's own, digit ordinals outside a
    # role ("1st blue, 3rd red, 2nd green" had been read in the order said)
    "Build it like a staircase: red on blue.",
    "Make a traffic light: red, yellow, green in a tower.",
    "Build it like the referee's: red on blue.",
    "Build it like a layer cake: a brown cube on the bottom, a white cube on that, and a pink cube on top.",
    "Stack: 1st blue, 3rd red, 2nd green.",
    "tower: bottom pink, 2nd gray, 3rd cyan, top red",  # a digit ordinal outside a role's "=" or ":" stays unread
    "Scatter it: put the red cube on the blue patch.",  # a heading whose verb changes the scene stays, refused
    "Build it like a pyramid: red on blue, green on red.",  # a heading naming another structure than its text's
    "Build it twice: red on blue.",  # a heading that repeats
    "Make a row of red and blue, with a green cube on top.",  # "with ... on top" of no single cube
    "Stack three cubes; the 3rd is red.",  # a rank alone: from which end? (it had been dropped, red anywhere in the tower)
    "Stack three cubes; the first is red.",
    "Stack three cubes; the second is red and the third is blue.",  # ranks with no first: the tower had been any order
    "Put the red cube on the blue patch. Anyway, put it on the green patch.",  # 'anyway' inside the text stays unread
])
def test_forty_second_session_refusals(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a label after its noun said first in the sentence ("Block 4" had lost its label: a red cube went on the patch)
    ("Block 4 on the red patch.", ["on_patch(4,patch:red)"]),
    ("Cube B in the front right corner.", ["in_region(B,front_right)"]),
    # labels listed before the noun they share, three or more ("the A, B and C cubes" had lost A)
    ("Line up the A, B, C and D blocks from left to right.", ["line[left_to_right](A,B,C,D)"]),
    ("Put the 1 and 2 cubes side by side.", ["next_to(1,2)"]),
])
def test_forty_third_session_label_readings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # layers of a pyramid of label cubes: refused in the forty-third session (no reader judged them, any cube at the apex
    # passed), read and judged by an InLayers since the forty-sixth
    ("Pyramid of three: the letter cubes B and A on the bottom, the letter C cube at the apex.", ["pyramid(A,B|C)"]),
    ("Build a pyramid of the digit cubes 1, 2 and 3 with 3 on top.", ["pyramid(1,2|3)"]),
])
def test_forty_third_session_label_pyramid_layers(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == sorted(expected)
    assert any(type(p).__name__ == "InLayers" for p in schema.goal_predicate().walk())


@pytest.mark.parametrize("text, expected", [
    # a wall's or pyramid's two layers said as one set of cubes below or on another: its bottom and top rows (the layers
    # had been dropped, and "on top of" read upside down; "under two" stays refused as a quantity)
    ("Build a wall at the back: two orange cubes beneath two pink cubes.", ["wall(orange,orange|pink,pink)@back"]),
    ("Build a wall: two orange cubes below two pink cubes.", ["wall(orange,orange|pink,pink)"]),
    ("Build a wall: two pink cubes on top of two orange cubes.", ["wall(orange,orange|pink,pink)"]),
    ("Build a pyramid: one green cube on top of two red cubes.", ["pyramid(red,red|green)"]),
])
def test_forty_third_session_layers_said_as_a_pair(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    "Use under five cubes.",  # a quantity still
    "Build a wall of red cubes under two blue cubes.",  # 'under two' (a hostile helper: the layers had been dropped)
    "Build a tower of A, B, C and D in any order, but C and D must be on top.",  # two cubes for one end
    "Build a tower of A, B and C, whichever goes where, A at the bottom, then B.",  # more of the order than its ends
    "Block 2 blue cubes next to the red cube.",  # a count, no label (the count had been dropped)
    "No one wants the red cube on the blue cube.",  # a negation ('no one')
])
def test_forty_third_session_quantity_and_negation_kept(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    # silent readings a hostile helper found (pre-existing): each now refused
    "Put all but the A, B and C cubes in a row.",  # an exclusion (the three had been lined up)
    "Put the A, B and C cubes in a row: C, A, B.",  # two orders (the second had been dropped)
    "Build a pyramid of letter cubes; A goes up top.",  # a label pyramid's layer (dropped)
    "Build a pyramid of the digit cubes 1 to 6, smallest up top.",
    "Ban list: the red cube on the blue cube.",  # a label that negates (read as the goal)
    "Veto note: the red cube on the blue cube.",
    "Cancellation note: red on blue.",
    "Place the first, second and third cubes in a row.",  # cubes by ranks nobody defined (four had been made up)
    "Put cube one on cube two.",  # cubes numbered in words (two coloured cubes had been made up)
    "Block four on the red patch.",
    "Block 10 on the red patch.",
])
def test_forty_third_session_silent_readings_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, end, fixed", [
    # a tower's order said free with an end given to one of its cubes: that end fixed, the rest free (each had been refused)
    ("Stack A, B and C into one tower. Any order is fine, but A must be at the bottom.", "bottom", "letter_a"),
    ("Tower: purple base, then the yellow and the white cubes above it in any order.", "bottom", "purple"),
    ("Stack red, blue and green into one tower in any order, with green on top.", "top", "green"),
])
def test_forty_third_session_any_order_with_an_end(text, end, fixed):
    from rpg.domain.predicates import AnchoredStack

    goal = check_feasibility(parse(text)).goal_predicate()
    assert isinstance(goal, AnchoredStack) and getattr(goal, end)
    assert (goal.objects[0] if end == "bottom" else goal.objects[-1]) == fixed


def test_forty_third_session_whichever_goes_where_frees_the_order():
    goal = check_feasibility(parse("Stack the red and blue cubes, whichever goes where.")).goal_predicate()
    assert type(goal).__name__ == "UnorderedStack"


@pytest.mark.parametrize("text, expected", [
    # a simile that pictures the relation the task already says (it had been refused over its unknown nouns)
    ("Put the black cube behind the white cube, like the monitor behind the singer.", ["behind(black,white)"]),
    ("Lay a row of five gray cubes along the back of the table, like a line of rocks.", ["line(gray,gray,gray,gray,gray)@back"]),
    ("Put the red cube on the blue cube, like a cherry on top.", ["stack(blue,red)"]),
])
def test_forty_fourth_session_a_simile_that_restates_the_relation(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # a simile with a relation of its own stays, to be read or refused
    "Put the red cube next to the blue cube, like a hat on a head.",
    # a comparison with cubes arranged otherwise: it had been read as a second stack the goal demanded
    "Put the red cube on the blue cube, like the green cube on the yellow cube.",
    "Put the red cube on the blue cube like the green cube is on the yellow cube.",
])
def test_forty_fourth_session_similes_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # label cubes listed by their kind, then placed (steer_stranger27 r019's base; the list had been read as two unlabelled
    # cubes and refused)
    ("Put the digit cubes 7 and 8 on the white patch.", ["on_patch(7,8,patch:white)"]),
    ("Put the letter cubes A and B on the white patch.", ["on_patch(A,B,patch:white)"]),
    ("Put the digit cubes 1, 2 and 3 on the red patch.", ["on_patch(1,2,3,patch:red)"]),
    ("Put the letter cubes A and B in the front left corner.", ["in_region(A,front_left)", "in_region(B,front_left)"]),
])
def test_forty_fourth_session_label_lists_placed(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # a label between "The" and its noun at a sentence's start: "The A block" had lost its label (read as an article: a red
    # cube went on B, silently), "The K block" had been refused
    ("The A block goes on top of the B block.", ["stack(B,A)"]),
    ("The K block goes on top of the M block.", ["stack(M,K)"]),
    ("The 3 cube goes in front of the 8 cube.", ["in_front_of(3,8)"]),
])
def test_forty_fourth_session_a_label_after_a_capital_the(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # a row's places said before the row word, the first at the text's start (stranger56; 'left' had been read as the
    # table's and refused)
    ("Orange on the far left, yellow in the middle, blue on the far right, all in one row.", ["line[left_to_right](orange,yellow,blue)"]),
    ("Orange on the left, yellow in the middle, blue on the right, all in one row.", ["line[left_to_right](orange,yellow,blue)"]),
    # (one end read as the row's by its words, the other as a side of the table: the two still pair)
    ("the red brick goes on the left, blue brick in the middle, green brick on the right – a row.",
     ["line[left_to_right](red,blue,green)"]),
    ("Cube red at leftmost, cube blue at rightmost, cube yellow in middle, make row.", ["line[left_to_right](red,yellow,blue)"]),
])
def test_forty_fourth_session_row_places_said_first(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_forty_fourth_session_a_swap_whose_end_is_said_in_full():
    """stranger56: the end of an exchange said in full after "so" is that end (the swap had been refused as a reference to
    the current scene); a swap with no end said stays refused."""
    text = "Swap things around so the black cube is on the white patch and the white cube is on the black patch."
    assert sorted(meaning(check_feasibility(parse(text)))) == ["on_patch(black,patch:white)", "on_patch(white,patch:black)"]
    with pytest.raises(BadInput):
        check_feasibility(parse("Swap the red cube and the blue cube."))


@pytest.mark.parametrize("text, expected", [
    # a label alone after a capitalised "The" (stranger56: "The 3 goes in front of the 8." had been read as no task)
    ("The 3 goes in front of the 8.", ["in_front_of(3,8)"]),
    ("The A goes on the B.", ["stack(B,A)"]),
])
def test_forty_fourth_session_a_bare_label_after_a_capital_the(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_forty_fourth_session_that_order_after_listed_letters():
    """stranger56: "in that order" after "the letters Q, R and S" refers to the letters listed (it had been refused as an
    order the speaker shows); with nothing listed it stays refused."""
    assert meaning(check_feasibility(parse("Put the letters Q, R and S in a row, in that order."))) == ["line[sequence](Q,R,S)"]
    with pytest.raises(BadInput):
        check_feasibility(parse("Stack the letters in that order."))


@pytest.mark.parametrize("text, expected", [
    # a structure of label cubes placed in a region (its labels had been re-read in lower case and the place refused)
    ("Stack the letter cubes A, B and C from bottom to top at the front of the table.", ["stack(A,B,C)@front"]),
    ("Put the letter cubes A, B and C in a row from left to right at the back of the table.", ["line[left_to_right](A,B,C)@back"]),
])
def test_forty_fourth_session_label_structures_placed(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # an arrow to a patch (stranger55, stranger56: read as no task)
    ("Two orange cubes -> the white patch.", ["on_patch(orange,orange,patch:white)"]),
    ("cube 5 -> red patch", ["on_patch(5,patch:red)"]),
])
def test_forty_fourth_session_an_arrow_to_a_patch(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # comparisons with cubes arranged otherwise (a hostile helper's probes: each had added the compared relation to the goal)
    "Stack the red cube on the blue cube, like on top of the green one.",
    "Put the red cube on the blue cube, the way the green cube is behind the yellow cube.",
])
def test_forty_fourth_session_comparisons_with_cubes_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a demonstrative structure is the definite one (stranger57: "that tower" had made a tower of two made-up cubes)
    ("Initially the orange cube is stacked on the purple cube. Put a cyan cube on top of that tower.",
     ["stack(purple,orange,cyan)", "start:stack(purple,orange)"]),
    ("Stack red on blue and move that stack to the left.", ["stack(blue,red)@left"]),
    ("black on white and put that stack in the back right", ["stack(white,black)@back_right"]),  # (stranger25: a chain said)
])
def test_forty_fifth_session_a_demonstrative_structure(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # a demonstrative structure nobody described: one the speaker sees (each had invented a red and blue tower, silently)
    "Put a cyan cube on top of that tower.",
    "Move that stack to the left side of the table.",
])
def test_forty_fifth_session_an_undescribed_demonstrative_structure_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # two counted groups, each in a structure of its own, joined by "and" or a comma (steer_stranger28: the second group's
    # count had been read against the first row and the text refused)
    ("Three white cubes in a row at the back of the table, and three black cubes in a row at the front of the table.",
     ["line(black,black,black)@front", "line(white,white,white)@back"]),
    ("Two pink cubes in a row at the front of the table, two purple cubes in a row at the back of the table.",
     ["line(pink,pink)@front", "line(purple,purple)@back"]),
])
def test_forty_fifth_session_two_counted_groups_in_structures_of_their_own(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_forty_fifth_session_a_second_group_that_refers_back_is_not_split():
    with pytest.raises(BadInput):
        check_feasibility(parse("Two white cubes in a row, and two black cubes in a row behind them."))


@pytest.mark.parametrize("text, expected", [
    # a row with one end said and the rest free (stranger57: refused, "end ... orders none of it"): an AnchoredLine
    ("Red at the left end of a row, with blue and green after it in any order.", ["line[left_end](red,blue,green)"]),
    ("Make a row of the orange, pink and gray cubes; the gray one must be at the right end.", ["line[right_end](orange,pink,gray)"]),
    ("Make a row of red, green, blue and yellow with red at the left end and blue at the right end.",
     ["line[left_end,right_end](red,green,yellow,blue)"]),
    ("Make a row of red, green and blue at the back of the table with the red cube on the far left.", ["line[left_end](red,blue,green)@back"]),
])
def test_forty_fifth_session_a_row_with_an_end_said_and_the_rest_free(text, expected):
    schema = check_feasibility(parse(text))
    assert sorted(meaning(schema)) == sorted(expected)
    assert not uncited(schema)  # each end cites its words


@pytest.mark.parametrize("text", [
    # an end said with more of the order, or an end of either side, or a cube in two ends: not read as an anchored row
    "Make a row of red, green and blue with red at the left end, then green.",
    "Make a row of red, green and blue with red at one end.",
    "Make a row of red, green and blue with red at the left end and red at the right end.",
])
def test_forty_fifth_session_a_row_end_with_more_said_is_not_anchored(text):
    try:
        schema = check_feasibility(parse(text))
    except BadInput:
        return
    assert not any(p.name == "anchored_line" for p in schema.goal_predicate().walk())


def test_forty_fifth_session_a_row_free_but_an_end_matches_only_all_its_completions():
    """An annotator's alternatives equal a row free but for its end only when they are every order it accepts: one
    order alone (the row fully ordered) is a stricter goal, and is not a match."""
    from rpg.schema.meaning import completions, matches_alternatives

    got = ["line[left_end](red,blue,green)"]
    assert sorted(c[0] for c in completions(got)) == ["line[left_to_right](red,blue,green)", "line[left_to_right](red,green,blue)"]
    assert matches_alternatives(["line[left_to_right](red,blue,green)", "line[left_to_right](red,green,blue)"], got)
    assert matches_alternatives(["line[right_to_left](green,blue,red)", "line[left_to_right](red,green,blue)"], got)
    assert not matches_alternatives(["line[left_to_right](red,blue,green)"], got)
    assert not matches_alternatives(["line(blue,green,red)"], got)
    assert completions(["stack(red,blue)"]) == [["stack(red,blue)"]]


@pytest.mark.parametrize("text, expected", [
    # stranger57's read lab texts, each refused before: "the rest in whatever order" (a reference), a single cube listed
    # with a counted group (the count lost), two cubes at a row's ends, "respectively" over three patches, a direction
    # before its list, "on either side", "comes next", a start said as a tower after a comma, a start in brackets or
    # "given"
    ("Build a tower of blue, green and black with the black cube on top; the rest in whatever order.", ["stack(blue,green,black)"]),
    ("Make a row out of the pink cube and the two cyan cubes.", ["line(cyan,cyan,pink)"]),
    ("Make a row of the two cyan cubes and the pink cube.", ["line(cyan,cyan,pink)"]),
    ("Put the green cube in the middle of a row, with the two white cubes at the ends.", ["line[left_to_right](white,green,white)"]),
    ("Place the orange, black and pink cubes on the cyan, purple and blue patches respectively.",
     ["on_patch(black,patch:purple)", "on_patch(orange,patch:cyan)", "on_patch(pink,patch:blue)"]),
    ("From left to right, place red, white, red.", ["line[left_to_right](red,white,red)"]),
    ("Row of three: yellow in the middle, red and blue on either side of it.", ["between(yellow;blue,red)", "line(blue,red,yellow)"]),
    ("Put red and blue on either side of the yellow cube.", ["between(yellow;blue,red)"]),
    ("Line the cubes up so that green is on the far left, blue comes next, then black, and pink is on the far right.",
     ["line[left_to_right](green,blue,black,pink)"]),
    ("There's a two-cube tower, red on top of white. Add a black cube to the top of it.",
     ["stack(white,red,black)", "start:stack(white,red)"]),
    ("Starting from a tower of green (bottom), yellow, white (top), unstack everything onto the table.",
     ["on_table(green)", "on_table(white)", "on_table(yellow)", "start:stack(green,yellow,white)"]),
    ("Given a stack with black at the bottom and gray on top, move the gray cube onto the red patch.",
     ["on_patch(gray,patch:red)", "start:stack(black,gray)"]),
])
def test_forty_fifth_session_lab_phrasings(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_forty_fifth_session_the_rest_in_any_order_leaves_the_others_free():
    goal = check_feasibility(parse("Build a tower of blue, green and black with the black cube on top; the rest in whatever order.")).goal_predicate()
    assert goal.name == "anchored_stack" and goal.top and not goal.bottom


@pytest.mark.parametrize("text", [
    # as many cubes as patches, or refused; two patches for three cubes
    "Place the orange, black and pink cubes on the cyan and purple patches respectively.",
])
def test_forty_fifth_session_respectively_with_unequal_lists_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a voice's label before its task with a count of the voice's own things, a name numbered, or "one" for the task itself
    # (steer_stranger28's bases: each had been refused over the count or "one")
    ("Two pots: the red cube onto the green patch and the black cube onto the blue patch.",
     ["on_patch(black,patch:blue)", "on_patch(red,patch:green)"]),
    ("Snooker lesson one: the green cube to the right of the brown cube.", ["right_of(green,brown)"]),
    ("Lads, quick one: put the red cube on the blue cube.", ["stack(blue,red)"]),
    ("Alright, last one for today: put the red cube on the blue cube.", ["stack(blue,red)"]),
])
def test_forty_fifth_session_voice_labels_with_their_own_counts(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # a count that may be the task's stays in the label, to be refused: a count of cubes, "them", "times", "just one"
    "Two of them: put the red cube on the blue cube.",
    "Three times: put the red cube on the blue cube.",
    "Pick one: put the red cube on the blue cube or on the green cube.",
])
def test_forty_fifth_session_voice_labels_that_count_the_task_stay(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    # a hostile helper's probes of this session's readings (forty-fifth session), each compiled silently wrong before its mend:
    # two cubes for one end, a cube beyond the row's list, cubes of a colour nobody said, a wish
    "Make a row of red, green and blue with red and green at the left end",
    "Make a row of red, green and blue. The gray one must be at the right end",
    "Make a row of three cubes with yellow at the left end",
    "Make a row with red at the left end",
    "Make a row of red, green and blue with red at the left end if possible",
    # "on either side of" a cube that is not the middle one
    "Put the green cube in the middle of a row, with red and blue on either side of the white cube",
    "Row of three: yellow in the middle, red and blue on either side of the green cube",
    # "them" with no cubes named, a demonstrative cube nobody named (cubes had been made up)
    "Make a row of them.",
    "Make a tower of them.",
    "Stack red on blue. Put green on top of that cube.",
    "Put green on top of that cube.",
    # a voice label's count of copies, levels or pairs (the count had been dropped)
    "Two copies: red on blue.",
    "Three levels: red on blue.",
    "Four stories: stack red, green and blue",
    "Two pairs: red on blue.",
    # "comes next" with no end said first: no order
    "Make a tower of red and blue, white comes next",
])
def test_forty_fifth_session_hostile_probes_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Make a row of three cubes: green in the middle, with the two white cubes at the ends", ["line[left_to_right](white,green,white)"]),
    ("Make a row of three cubes: green in the middle, white at the ends", ["line[left_to_right](white,green,white)"]),
    ("Row of three: yellow in the middle, red and blue on either side of the yellow cube.",
     ["between(yellow;blue,red)", "line(blue,red,yellow)"]),
    ("Put a pink cube on top of the red cube, and a brown one on top of that one.", ["stack(red,pink,brown)"]),
    ("Take the red, green and blue cubes and make a tower of them.", ["stack(red,green,blue)"]),
])
def test_forty_fifth_session_hostile_probes_read(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # a pyramid of label cubes (stranger55-58: each had been refused, "label cubes in a pyramid's layers")
    ("Arrange the 5, 6 and 7 cubes into a pyramid with 7 at the top.", ["pyramid(5,6|7)"]),
    ("Build a pyramid with the digit cubes 2, 4 and 6 at the base and 8 at the top.", ["pyramid(2,4,6|8)"]),
    ("Build a small pyramid from the letter cubes X, Y and Z, with Y on top.", ["pyramid(X,Z|Y)"]),
    ("Make a little pyramid with letter cubes: A and B at the bottom, C on top.", ["pyramid(A,B|C)"]),
    ("Build a pyramid from the letter cubes A, B and C.", ["pyramid(A,B,C)"]),
    ("Build a pyramid of the digit cubes 1 to 6 with 1, 2 and 3 on the bottom and 6 on top.", ["pyramid(1,2,3|4,5|6)"]),
    # layer sizes written as digits are no digit cubes (stranger24: "3/2/1" had been read as the cubes 1, 2 and 3)
    ("need a pyramid 3/2/1, colors dont matter", ["pyramid(red,red,red,red,red,red)"]),
])
def test_forty_sixth_session_a_pyramid_of_label_cubes(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_forty_sixth_session_a_label_pyramid_judges_the_layers_said():
    schema = check_feasibility(parse("Arrange the 5, 6 and 7 cubes into a pyramid with 7 at the top."))
    layers = [p for p in schema.goal_predicate().walk() if type(p).__name__ == "InLayers"]
    assert len(layers) == 1
    by_label = {a.name: a.label for a in schema.assets}
    assert {by_label[n]: k for n, k in zip(layers[0].objects, layers[0].levels, strict=True)} == {"5": 0, "6": 0, "7": 1}


@pytest.mark.parametrize("text", [
    "Build a pyramid of the letter cubes A, B and C with D on top.",  # four labels: no pyramid
    "Build a pyramid of the digit cubes 1, 2 and 3 sorted ascending.",  # an order beyond the layers (had been dropped)
    "Build a pyramid of the digit cubes 1, 2 and 3 with 3 on top of 1.",  # a relation beyond the layers (had been dropped)
    "Make a pyramid of letter cubes A, B and C with A and B on top.",  # a layer given more than it holds
    "A pyramid of the letter cubes A, B, C, D, E and F with F on top.",  # five labels whose layers are unsaid
    "Build a pyramid of six cubes from the letter cubes A, B and C.",  # a count the labels do not make
    # words of layers or orders no layer role reads (a hostile probe: each had been dropped, any cube in any site)
    "Build a pyramid of the letter cubes A, B and C with A resting upon B and C",
    "Build a pyramid of the letter cubes A, B and C; the top cube is A",
    "Build a pyramid: first layer A, B and C; second layer D and E; third layer F",
    "Lay the letter cubes A, B and C flat on the table in a triangle, A at the top",
    "Build a 3D pyramid: the letter cubes A, B, C and D on the bottom and E on top",
    "Build a pyramid of the letter cubes A, B, C, D, E and F, but use only A, B and C",
    "Build a pyramid of the letters A, B and C so it reads CAB",
    "Build a pyramid of the letter cubes A, B and C on top of each other",
])
def test_forty_sixth_session_a_label_pyramid_said_beyond_its_layers_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a pyramid's layers said by counts with "in the middle" (stranger24/27/28/29: read as the table's centre, refused)
    ("make a pyramid three on the bottom two in the middle one on top any cubes", ["pyramid(red,red,red,red,red,red)"]),
    ("Build a pyramid of six red cubes, three on the bottom layer, two in the middle, one on top.",
     ["pyramid(red,red,red,red,red,red)"]),
    # a base said "along the bottom" or "below ... and ... on top" (stranger51/53/56/58: refused or a base of three)
    ("A four-cube pyramid: brown, black and gray along the bottom, red on top.", ["pyramid(black,brown,gray|red)"]),
    ("a pyramid with the two purple cubes below and the pink cube on top.", ["pyramid(purple,purple|pink)"]),
    # "the base is blue, blue, green": a layer, not a tower listed from its base (it had been refused)
    ("Make a 3-2-1 pyramid: the base is blue, blue, green; the middle is yellow, yellow; the top is red.",
     ["pyramid(blue,blue,green|yellow,yellow|red)"]),
])
def test_forty_sixth_session_pyramid_layers_said_in_other_words(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # a voice's label whose structure noun is the task's own kind, or qualifies a thing of the voice's world
    # (steer_stranger29: each base had been refused)
    ("Tungsten tower: stack a gray cube on a black cube.", ["stack(black,gray)"]),
    ("Tower captain speaking: stack the red cube on the yellow cube.", ["stack(yellow,red)"]),
    ("Grid reference: the digit cubes 4, 0, 2 in a row, left to right.", ["line[left_to_right](4,0,2)"]),
    # the label that names the task's structure stays the task's ("Pyramid task: ...")
    ("Pyramid task: bottom layer purple, purple, brown; top layer blue.", ["pyramid(brown,purple,purple|blue)"]),
    # a label with a count or a spec stays whole, to be read
    ("pile-5 [region=back]: pile red cubes", ["pile(red,red,red,red,red)@back"]),
])
def test_forty_sixth_session_a_voice_label_with_a_structure_noun(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text", [
    # a label's structure that is not the task's ("contour lines" over a wall) or that says more (a colour)
    "Contour lines: build a wall with four green cubes on the bottom layer and four yellow cubes on top.",
    "Red tower: stack the blue cube on the green cube.",
    "Twin towers: stack a red cube on a blue cube.",  # a hostile probe: one tower had been built, the label dropped
    "Parallel rows: put three red cubes in a row.",
    "Countdown row: put the digit cubes 3, 1 and 2 in a row.",
])
def test_forty_sixth_session_a_voice_label_that_may_say_the_task_stays(text):
    # (also "Twin towers", "Parallel rows", "Countdown row": a label that may count or order; see the parametrize list)
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    # a structure's place said between its listed cubes and its ends (stranger58: the list had been cut from its ends)
    ("Build a tower of the cyan, orange and white cubes on the right side, cyan at the bottom and white at the top.",
     ["stack(cyan,orange,white)@right"]),
    ("Make a row of the red, green and blue cubes at the front, red on the left and blue on the right.",
     ["line[left_to_right](red,green,blue)@front"]),
])
def test_forty_sixth_session_a_place_between_a_list_and_its_ends(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, expected", [
    # the side of a structure being described, its cubes named by no colour (stranger58: the side had been left unread)
    ("Build a row of three cubes on the left side.", ["line(blue,green,red)@left"]),
    ("Make a pile of four cubes on the right side.", ["pile(blue,green,red,yellow)@right"]),
    # "the two red ones at the ends" (stranger58: "ones" had kept the count against one cube)
    ("Row of three cubes with the brown one in the middle and the two red ones at the ends.", ["line[left_to_right](red,brown,red)"]),
])
def test_forty_sixth_session_sides_and_ends_of_a_structure(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


@pytest.mark.parametrize("text, end", [
    # a tower said by one end and "the other N (...) in any order above/under it" (stranger51/54/58: no task had been found)
    ("Tower of four: yellow on the bottom, and the other three (red, pink, brown) in any order above it.", "bottom"),
    ("Tower of three: blue on top; the other two, red and white, can go in either order under it.", "top"),
])
def test_forty_sixth_session_a_tower_of_one_end_and_the_others_in_any_order(text, end):
    goal = check_feasibility(parse(text)).goal_predicate()
    assert type(goal).__name__ == "AnchoredStack" and getattr(goal, end) and not getattr(goal, {"top": "bottom", "bottom": "top"}[end])


@pytest.mark.parametrize("text", [
    "Tower of four cubes: the gray one at the base, the other three (red, pink) in any order above it.",  # two listed of three
    "Tower of three: blue on top; the other two, red and white, can go in either order above it.",  # above the top
])
def test_forty_sixth_session_a_tower_of_one_end_that_does_not_agree_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


def test_forty_sixth_session_a_row_of_one_end_and_the_others_in_any_order():
    # stranger58: "the other two, orange and cyan, in any order" after the row's left end had been refused
    assert meaning(check_feasibility(parse("Row of three: white on the far left, then the other two, orange and cyan, in any "
                                           "order."))) == ["line[left_end](white,cyan,orange)"]


@pytest.mark.parametrize("text", ["Make two rows: one of three red cubes and one of three blue cubes.",
                                  "Make two rows: one of three red cubes, one of three blue cubes."])
def test_forty_sixth_session_two_rows_each_said_after_a_colon(text):
    # stranger58: "two rows: one of ..." had found no task
    assert sorted(meaning(check_feasibility(parse(text)))) == ["line(blue,blue,blue)", "line(red,red,red)"]


def test_forty_sixth_session_a_person_named_after_a_thing_is_no_such_thing():
    """"archers" are close to "arch" in the embedding (a shape the domain does not build): a person named after a thing is
    not refused as that thing; "arches" still are."""
    from rpg.schema import senses

    assert senses.sense("archers").kind == "unknown"
    assert senses.sense("arches").kind == "shape"
    with pytest.raises(BadInput):
        check_feasibility(parse("Build an arch of five cubes."))


def test_forty_sixth_session_layer_words_that_are_no_layers_keep_their_reading():
    # a hostile probe: a tower "by the wall" listed from its top had been read from the bottom; a pyramid's base "placed
    # in the middle" had lost the table's centre
    assert meaning(check_feasibility(parse("Stack three cubes into a tower by the wall: the top is red, then blue, then "
                                           "green."))) == ["stack(green,blue,red)"]
    assert meaning(check_feasibility(parse("Build a pyramid of six blue cubes, its base placed in the middle"))) == [
        "pyramid(blue,blue,blue,blue,blue,blue)@center"]


@pytest.mark.parametrize("text, expected", [
    # a tower said cube by cube with label cubes (stranger59: "the block marked 5 on it" had been dropped, silently)
    ("Put the block marked 9 at the bottom, the block marked 5 on it, and the block marked 1 on top.", ["stack(9,5,1)"]),
    ("Put the 9 block at the bottom, then the 5 block on it, then the 1 block on top.", ["stack(9,5,1)"]),
    # a bottom, a middle and a top said: a tower's, whatever names it ("in the middle" had been the table's centre)
    ("Put block 9 at the bottom, block 5 in the middle and block 1 on top.", ["stack(9,5,1)"]),
    ("Put the A block at the bottom, the B block in the middle and the C block on top.", ["stack(A,B,C)"]),
    ("Put the red block at the bottom, the blue block in the middle and the green block on top.", ["stack(red,blue,green)"]),
    ("Red on top, green in the middle, blue on the bottom.", ["stack(blue,green,red)"]),
])
def test_forty_seventh_session_a_tower_said_cube_by_cube_with_labels_and_roles(text, expected):
    # (a second hostile tester's "Red on top, green in the middle, blue on the bottom." had put green at the table's centre
    # and was refused since; a top, a middle and a bottom said are a tower's: read so now, below)
    assert meaning(check_feasibility(parse(text))) == expected


def test_forty_seventh_session_a_label_said_by_how_it_is_marked_must_have_a_place():
    # the accounting weighs the text as read too: "the block marked 5" is the digit 5 cube, which the task must hold
    from rpg.schema.accounting import unaccounted
    from rpg.schema.reading import features

    f = features("Put the block marked 9 on the block marked 5.")
    schema = check_feasibility(parse("Put the block marked 9 on the block marked 1."))
    assert unaccounted(f, schema) is not None


@pytest.mark.parametrize("text, expected", [
    # a statement about a third party of a voice's world, before the task (stranger59: each had been refused)
    ("Roofing's a slow trade. Put the yellow cube to the right of the cyan cube.", ["right_of(yellow,cyan)"]),
    ("Varnish dries at its own pace. Put the red cube between the yellow cube and the green cube.",
     ["between(red;green,yellow)"]),
    ("A good bookbinder never rushes the press. Build a tower: blue at the base, gray in the middle, red on top.",
     ["stack(blue,gray,red)"]),
    ("Deep in the cavern the stalagmites grow slowly. Build a tower: gray at the base, then brown, then cyan on top.",
     ["stack(gray,brown,cyan)"]),
    ("Sewing can wait; put the yellow cube on the orange patch, as neat as fresh endpaper.", ["on_patch(yellow,patch:orange)"]),
    ("A luthier chooses tonewood slowly; your job is simpler: put the orange cube on the blue cube.", ["stack(blue,orange)"]),
    # a simile before the task
    ("Like laying shingles from the eaves to the ridge, build a tower: orange, then yellow, then white, bottom to top.",
     ["stack(orange,yellow,white)"]),
])
def test_forty_seventh_session_a_voice_speaks_of_its_own_world(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Never rush. Put the red cube on the blue cube.",  # said to the one who does the task: a manner, refused
    "Time is short. Put the red cube on the blue cube.",  # a demand on the task, not a third party's
    "Order is key. Put the red cube on the blue cube.",
    "The gondolier stacks oars twice. Put the red cube on the blue cube.",  # a scene-changing verb, a repetition
    "Never rush; put the red cube on the blue cube.",
    "It dries slowly. Put the red cube on the blue cube.",  # "it" may be the task's
    "Stack the red cube on the blue cube a hundred times.",  # a repetition (it had compiled: "hundred" was no count)
    "Make a tower of one thousand cubes.",  # a quantity no task holds (it had been an unknown word)
])
def test_forty_seventh_session_what_may_bear_on_the_task_is_not_a_world_statement(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


def test_forty_seventh_session_a_count_beyond_any_task_is_refused_as_a_quantity():
    from rpg.schema.reading import Inexpressible

    with pytest.raises(Inexpressible) as exc:
        parse("Make a tower of one thousand cubes.")
    assert exc.value.kind == "quantity" and "1000 cubes" in str(exc.value)


@pytest.mark.parametrize("text, expected", [
    # free order said in other words (stranger59: refused)
    ("From the luthier's workshop: build a tower of the gray, cyan and white cubes in whichever order sounds best to you.",
     ["stack(gray,cyan,white)"]),
    ("Given the blue, cyan and white cubes, put them all in one stack; the order is up to you.", ["stack(blue,cyan,white)"]),
    ("Row of the yellow, green, purple and orange cubes; the orange one goes on the far right, the rest however you like.",
     ["line[right_end](green,purple,yellow,orange)"]),
    # a pyramid's top said after a comma, its base said "a base of" (stranger59: a pyramid of six, or refused)
    ("Make a pyramid from two white cubes and a black cube, the black cube at the peak.", ["pyramid(white,white|black)"]),
    ("Pyramid with a base of the letter blocks D, G and T and the letter block X on top.", ["pyramid(D,G,T|X)"]),
    ("Make a pyramid with yellow along the base", ["pyramid(yellow,yellow,yellow|blue,red|green)"]),
    # several structures counted off after a heading (stranger59: refused)
    ("Two towers, each three tall: the first red-blue-green bottom to top, the second all gray.",
     ["stack(gray,gray,gray)", "stack(red,blue,green)"]),
    ("Make two rows: one of three red cubes at the front of the table and one of three green cubes at the back.",
     ["line(green,green,green)@back", "line(red,red,red)@front"]),
    ("Two towers, three cubes each: one built from red cubes and one built from blue cubes.",
     ["stack(blue,blue,blue)", "stack(red,red,red)"]),
])
def test_forty_seventh_session_said_in_other_words(text, expected):
    assert sorted(meaning(check_feasibility(parse(text)))) == sorted(expected)


def test_forty_seventh_session_free_orders_stay_free():
    # "the rest however you like", "in whichever order sounds best": the order is left free in the goal, not demanded
    tower = check_feasibility(parse("Build a tower of the gray, cyan and white cubes in whichever order sounds best to you."))
    assert [type(p).__name__ for p in tower.goal_predicate().walk()] == ["UnorderedStack"]
    anchored = check_feasibility(parse("Tower of red, blue and green with red at the bottom, the rest wherever you like."))
    assert repr(anchored.goal_predicate()) == "AnchoredStack(objects=['red', 'blue', 'green'], bottom=True)"


@pytest.mark.parametrize("text, expected", [
    # read material (stranger58): a pile said by its verb and a side, a radio's acknowledgement, a voice's absolute phrases,
    # the end state "the robot needs to end with" (each had been refused)
    ("Pile four cubes, any colours, on the right side.", ["pile(blue,green,red,yellow)@right"]),
    ("Copy that. Put the red cube on the blue cube.", ["stack(blue,red)"]),
    ("Dispatch to robot unit, be advised: stack the purple cube on top of the yellow cube, copy?", ["stack(yellow,purple)"]),
    ("Helmet on, arc struck: pile the pink, purple and gray cubes together in the center.", ["pile(gray,pink,purple)@center"]),
    ("Flux is on, joint is prepped: put the cyan cube next to the black cube.", ["next_to(black,cyan)"]),
    ("For this episode the robot needs to end with the blue cube resting on the white patch.", ["on_patch(blue,patch:white)"]),
])
def test_forty_seventh_session_read_material_said_in_other_words(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("label", [
    "Red on, blue off",  # colours are the task's, not a voice's things
    "Table cleared, cubes scattered",  # the domain's things, a scene-changing state
    "Gripper open",  # the robot's part: may bear on the task
    "Helmet on, stack placed",
])
def test_forty_seventh_session_absolute_phrases_that_may_bear_on_the_task_are_no_voice_label(label):
    from rpg.schema.reading import _absolute_phrases

    assert not _absolute_phrases(label)
    assert _absolute_phrases("Helmet on, arc struck") and _absolute_phrases("Mask down, torch lit")


def test_forty_seventh_session_a_copy_of_a_structure_stays_refused():
    with pytest.raises(BadInput):
        check_feasibility(parse("Copy that tower with the red cubes."))


@pytest.mark.parametrize("text", [
    # a hostile probe of this session's changes: each had compiled, silently dropping what its words said
    "Make two towers: the first of three red cubes, the second of three green cubes, the green one taller.",
    "Make two rows: one of three red cubes and one of three green cubes, left to right.",
    "Make two rows: one of three red cubes and one of three green cubes, touching.",
    "The clock never waits; put the red cube on the blue cube.",  # a time limit said of a third party
    "The buzzer will not wait. Put the red cube on the blue cube.",
    "The deadline is soon; put the red cube on the blue cube.",
    "The bot never rushes. Put the red cube on the blue cube.",  # the robot under another name
    "The machine never hurries. Put the red cube on the blue cube.",
    "Like laying shingles from the ridge to the eaves, build a tower: orange, then yellow, then white.",  # a simile's way
    "Like an island in the middle, put the red cube on the blue cube.",  # a simile's place
    "Put the red cubes at the bottom, the green cube in the middle and the blue cube on top.",  # how many red: unsaid
    # older silent errors it found
    "Put block b in the middle.",  # a lower-case label dropped, a red cube centred
    "Put block a at the bottom, block b in the middle and block c on top.",
    "Make a tower of sixty-five cubes.",  # had been a tower of five
    "Put five hundred cubes in a pile.",
    "Stack the red cube on the blue cube twenty times.",  # a repetition
    "Stack the red cube on the blue cube eleven times.",
])
def test_forty_seventh_session_hostile_probe_silent_errors_are_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Use block 9 and block 5 only: stack 9 on 5.", ["stack(5,9)"]),  # had been reversed: 9 under 5
    ("Build the 3 cube tower from the red, blue and green cubes.", ["stack(red,blue,green)"]),  # a digit-3 cube made up
    ("Make a pyramid with yellow along the base and blue in the middle.", ["pyramid(yellow,yellow,yellow|blue,blue|red)"]),
    ("Make a pyramid of six cubes with yellow along the base.", ["pyramid(yellow,yellow,yellow|blue,red|green)"]),
    ("Make a pyramid of 6 cubes whose base is yellow.", ["pyramid(yellow,yellow,yellow|blue,red|green)"]),
    ("Build a pyramid from two gray cubes, the black cube at the tip.", ["pyramid(gray,gray|black)"]),
    ("Sewing can wait; put the yellow cube on the orange patch.", ["on_patch(yellow,patch:orange)"]),
])
def test_forty_seventh_session_hostile_probe_readings(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    # read material (steer_stranger29's bases): labels listed after "between the letter cubes", and an alternation
    # written out after its pair (each had been refused)
    ("Captain's call: put the letter cube W between the letter cubes A and B.", ["between(W;A,B)"]),
    ("Put the digit cube 5 between the digit cubes 1 and 2.", ["between(5;1,2)"]),
    ("Scale bar: four cubes in a row, alternating black and white, left to right black, white, black, white.",
     ["line[left_to_right](black,white,black,white)"]),
])
def test_forty_seventh_session_steering_bases_read(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


def test_forty_seventh_session_an_alternation_written_out_otherwise_is_two_orders():
    with pytest.raises(BadInput):  # the pair says black first, the list white first: which order is not one
        check_feasibility(parse("Four cubes in a row, alternating black and white, left to right white, black, white, black."))


@pytest.mark.parametrize("text, expected", [
    # a radio's sign-off after the task (stranger54, read material: refused as an unknown word or an action)
    ("Approach control: bring the brown cube in behind the gray cube. Wilco?", ["behind(brown,gray)"]),
    ("Traffic advisory: build a stack of three, green at the bottom, white in the middle, orange on top. Acknowledge.",
     ["stack(green,white,orange)"]),
])
def test_forty_seventh_session_a_radio_sign_off(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


def test_forty_seventh_session_last_after_the_lists_last_then():
    # "then green last" says again that green ends the list ("last" had been an unknown word); "last" before another
    # "then" is not read
    assert meaning(check_feasibility(parse("Stack red first, then blue, then green last."))) == ["stack(red,blue,green)"]
    with pytest.raises(BadInput):
        check_feasibility(parse("Stack red first, then blue last, then green."))


def test_forty_seventh_session_a_pyramid_top_of_several_after_the_base_list():
    # a hostile probe: "... and yellow and pink on top" had put yellow in the base, silently; a pyramid with two on top and
    # no layer between is refused; one on top is read
    with pytest.raises(BadInput):
        check_feasibility(parse("Pyramid with a base of red, blue and green and yellow and pink on top."))
    assert meaning(check_feasibility(parse("Pyramid with a base of red, blue and green and yellow on top."))) == [
        "pyramid(blue,green,red|yellow)"]


@pytest.mark.parametrize("text", ["After 5 pm, move the pink cube to the left side.",  # stranger55/56 (read): had compiled
                                  "By 10:30, stack the red cube on the blue cube.",
                                  "At 3 o'clock, put the red cube on the blue cube."])
def test_forty_seventh_session_a_time_of_day_is_refused_as_time(text):
    from rpg.schema.reading import Inexpressible

    with pytest.raises(Inexpressible) as exc:
        check_feasibility(parse(text))
    assert "about time" in str(exc.value)


@pytest.mark.parametrize("text, expected", [
    # an opening adjunct of a voice's occasion (stranger60: each had been refused over its unknown words)
    ("Etymology aside, put the black cube in front of the cyan cube.", ["in_front_of(black,cyan)"]),
    ("For the keyframes I need a row of the red, orange and pink cubes, reading left to right in that order.",
     ["line[left_to_right](red,orange,pink)"]),
    ("For this mosaic panel I want the pink cube set between the cyan cube and the brown cube.", ["between(pink;brown,cyan)"]),
    ("In this trial the agent must arrange the red and yellow cubes in a row, from left to right in that order.",
     ["line[left_to_right](red,yellow)"]),
    ("Per the thesaurus, put the orange cube beside the purple cube.", ["next_to(orange,purple)"]),
    ("Spell HI so that H is on the left.", ["line[left_to_right](H,I)", "reads(H,I;direction=left_to_right,face=up,text=HI)"]),
    ("Put the red cube on the green patch and the blue cube on the same patch.", ["on_patch(blue,red,patch:green)"]),
    ("Gather each red cube into a pile on the left.", ["pile(red,red,red)@left"]),
    # a voice's label with its own table, an idiom of a structure noun, fillers; towers counted by a coloured heading and
    # said by their places; a closing "that's the ..." naming what was done
    ("Pause table: put the brown cube on the green patch.", ["on_patch(brown,patch:green)"]),
    ("Line of sight check: put the black cube in front of the gray cube.", ["in_front_of(black,gray)"]),
    ("Chip stack for the showdown: a tower of two blue cubes in the front left corner of the table.",
     ["stack(blue,blue)@front_left"]),
    ("Two gray towers, each three cubes tall, one on the left side of the table and one in the centre.",
     ["stack(gray,gray,gray)@center", "stack(gray,gray,gray)@left"]),
    ("Two rows, a row of three red cubes at the front of the table and a row of three blue cubes at the back.",
     ["line(blue,blue,blue)@back", "line(red,red,red)@front"]),
    ("Stack a white cube on a red cube, and stack a white cube on a blue cube, two separate towers.",
     ["stack(blue,white)", "stack(red,white)"]),
    ("Put a yellow cube on the green patch and a purple cube on the green patch too, that's the pot.",
     ["on_patch(purple,yellow,patch:green)"]),
    # a wall's two layers said below and above them (the layers had been lost: one course of four, silently)
    ("Build a wall in the center with two black cubes below and two gray cubes above them.",
     ["wall(black,black|gray,gray)@center"]),
    ("Sailors stow their gear low and heavy: build a wall with two brown cubes below and two black cubes above them.",
     ["wall(brown,brown|black,black)"]),
    # the others' order left free in other words
    ("A single tower of the pink, brown and gray cubes, with pink at the very top. The order of the other two is free.",
     ["stack(brown,gray,pink)"]),
    ("Put the red, blue and green cubes in a row, order unimportant.", ["line(blue,green,red)"]),
    # labels after "that" or a colon
    ("Stack the letter blocks so that C is at the bottom, B above it and A on top.", ["stack(C,B,A)"]),
    ("Stack the blocks: A at the bottom, B in the middle and C on top.", ["stack(A,B,C)"]),
    # a row from a said end, then the next ones
    ("Row of three cubes, purple at the far left, then cyan, then yellow at the far right.",
     ["line[left_to_right](purple,cyan,yellow)"]),
    ("A row: purple on the right, then cyan, then yellow.", ["line[right_to_left](purple,cyan,yellow)"]),
    ("Make a pile of any four cubes on the right side.", ["pile(blue,green,red,yellow)@right"]),
    ("Gather every pink cube into one pile.", ["pile(pink,pink,pink)"]),
    ("Two stacks please - one with black under white, the other with purple under cyan.",
     ["stack(black,white)", "stack(purple,cyan)"]),
    # a pyramid of two layers, each said by its count, and nothing above (its peak had been made up, or refused)
    ("Build a pyramid with three red cubes on the bottom layer and two white cubes on the layer above them.",
     ["pyramid(red,red,red|white,white)"]),
    ("Build a pyramid: three red cubes on the bottom layer and two white cubes on top.", ["pyramid(red,red,red|white,white)"]),
    ("Build a pyramid of five cubes: three red on the bottom and two white on top.", ["pyramid(red,red,red|white,white)"]),
])
def test_forty_eighth_session_what_a_voice_frames_and_what_it_orders(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "For a moment, put the red cube on the blue cube.",  # a time
    "For ten seconds, put the red cube on the blue cube.",
    "For each of them, put the red cube on the blue cube.",  # a reference
    "For the other one, put the red cube on the blue cube.",
    "In this drawer, put the red cube on the blue cube.",  # an object that may hold a cube
    "In the bowl, put the red cube.",
    "Between the mugs, put the red cube.",
    "In this picture, the red cube is on the blue cube.",  # something seen
    # a hostile helper's: an adjunct of a viewpoint, a document, a start state, an unwanted or turned state, copies
    "For the viewer, put the red cube left of the blue cube.",
    "Per guest, put a red cube on a blue cube.",
    "For the setup I need the red cube on the blue cube.",
    "Direction aside, put the red cube left of the blue cube.",
    "Per the schematic, build a wall of six cubes.",
    "In this reflected setup, put the red cube left of the blue cube.",
    "For the counterexample, put the red cube on the blue cube.",
    "Between the bookends, put the red cube on the blue cube.",
    "in the bowl -- put the red cube on the blue cube.",  # a dash clause is not dropped
    "this is the starting state -- put the red cube on the blue cube",
    # a cube said beyond two layers, or a whole pyramid: no two-layer reading
    "Build a pyramid with three red cubes on the bottom layer and two white cubes on top, and one cube at the very top.",
    "Build a pyramid with three red cubes on the bottom layer and two white cubes on top. Then put a cube on top.",
    "Build a 3D pyramid with three red cubes on the bottom and two white on top.",
    "Build a pyramid with three red cubes on the bottom layer and two white cubes on top; the highest cube is up to you.",
    # each cube into a structure of its own, or some of them
    "Put each red cube into a tower of its own.",
    "Put each red cube into a pile, two per pile.",
    "Put each red cube into a pile but one.",
    # a letter after "that" where no label cube is named
    "Stack the red, green and blue cubes so that A is on top.",
    # a word's or a rainbow's order is not free
    "Spell CAB in a row, order unimportant.",
    "Make a rainbow row, in any order.",
    # a copy of a structure said, or a patch never named ("the same"): its cubes or colour had been made up
    "Two stacks please - one with red on blue, the other one the same.",
    "Build two stacks: one with red on blue, the other the same.",
    "Build two stacks: one with red on blue, the other with the same colours.",
    "Put the red cube on the blue cube and the green cube on the same patch.",
    # a second hostile helper's: a heading's colour the parts contradict, a person's or a copy's label, a naming tail that
    # calls the goal unwanted
    "Two gray towers: red on blue, and green on yellow.",
    "Two gray towers, each three tall: the first red-blue-green, the second on the left.",
    "Opponent's table: put the red cube left of the blue cube.",
    "Duplicate table: stack a red cube on a blue cube.",
    "Line of dozens: stack a red cube on a blue cube.",
    "Put the red cube left of the blue cube, that's the decoy.",
    "Stack 1 on 2.",  # digit cubes or counts? (it had been two cubes in any order, silently)
    # a pyramid said by two layers and more: a middle layer, a total of six, a height of three
    "Build a pyramid with three red cubes on the bottom layer and two white cubes in the middle.",
    "Build a pyramid of six cubes: three red on the bottom and two white on top.",
    "Build a pyramid with three red cubes on the bottom and two white cubes on top, three layers high.",
])
def test_forty_eighth_session_an_adjunct_or_layer_that_bears_on_the_task_is_not_dropped(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


# ---------------------------------------------------------------------------
# forty-ninth session: stranger61 (development material from this session)
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("text, expected", [
    ("Jumpmaster's call: the red cube touches down on top of the blue cube.", ["stack(blue,red)"]),  # not also next to it
    ("The red cube lands on top of the blue cube.", ["stack(blue,red)"]),
    ("The red cube settles next to the blue cube.", ["next_to(blue,red)"]),
    ("The orange cube balances on top of the gray cube.", ["stack(gray,orange)"]),
    ("The red cube touches the blue cube.", ["next_to(blue,red)"]),  # touching stays next to
])
def test_forty_ninth_session_coming_to_rest_on_a_cube_is_being_on_it(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text", [
    "Stack 2.5 orange cubes on top of each other.",  # had been five orange cubes
    "Put 1.5 red cubes in a row.",
    "Build a tower of one and a half blue blocks.",
    "Stack half a red cube on the blue cube.",
])
def test_forty_ninth_session_a_count_that_is_not_whole_is_refused_as_a_quantity(text):
    with pytest.raises(Inexpressible, match="quantity|not a whole number"):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    "Initially all cubes are scattered on the table. Goal: orange on top of purple.",  # the order cited by "on top of"
    "A line of three cubes: black in the centre, orange at one end, purple at the other.",  # the between by "in the centre"
])
def test_forty_ninth_session_every_constraint_cites_its_words(text):
    assert uncited(check_feasibility(parse(text))) == []


def test_forty_ninth_session_a_one_end_line_written_with_its_end_matches_that_line():
    from rpg.schema.meaning import matches_alternatives

    got = ["line[right_end](white,yellow,black)"]
    assert matches_alternatives(["line[right_end](white,yellow,black)", "line[left_to_right](yellow,white,black)"], got)
    assert not matches_alternatives(["line[left_end](white,yellow,black)"], got)
    assert not matches_alternatives(["line[left_to_right](white,yellow,black)"], got)  # one order of two it accepts


@pytest.mark.parametrize("text, expected", [
    ("Goal: a three-cube tower of red, green and blue.", ["stack(red,green,blue)"]),  # one cube of each, not three red
    ("A tower of 3 cubes made of red.", ["stack(red,red,red)"]),
    ("Make a row with the yellow cube in the middle and the blue and red cubes on either side.",
     ["between(yellow;blue,red)", "line(blue,red,yellow)"]),
    ("Initially the pink cube sits on the cyan cube. Move the pink cube down to the table.",
     ["on_table(pink)", "start:stack(cyan,pink)"]),
])
def test_forty_ninth_session_what_stranger61_said_plainly(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text, kind", [
    ("stack orange, pink, cyan - whichever order", "UnorderedStack"),  # "whichever" had been an unknown word
    ("Stack orange, pink and cyan in whichever order.", "UnorderedStack"),
    ("Stack orange, pink and cyan from the bottom up.", "Stack"),
])
def test_forty_ninth_session_whichever_order_frees_the_order(text, kind):
    assert [type(p).__name__ for p in check_feasibility(parse(text)).goal_predicate().walk()] == [kind]


@pytest.mark.parametrize("text", [
    "The white cube starts behind the brown cube.",  # a start the tool does not build (had been the goal, silently)
    "The white cube starts behind the brown cube. Put it on the brown cube.",
    "The white cube begins next to the brown cube.",
    "The red cube starts on the blue patch. Put it on the green patch.",
    "Red starts the row, then blue, then green.",  # an order the row read had dropped
    "The white cube waits behind the brown cube.",  # a verb of time or motion is not dropped
    "The white cube rolls behind the brown cube.",
    "The red cube spawns behind the blue cube.",
    "The red cube hates sitting on the blue cube.",
])
def test_forty_ninth_session_a_start_order_or_time_is_not_dropped(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text", [
    # a hostile helper's (forty-ninth session): a start, a past, a later motion, a stay, a wish said around a goal's words
    "the red cube starts at the back left corner",
    "the red cube starts right on top of the blue cube",
    "the red cube's starting place is behind the blue cube",
    "the starting position of the red cube is on top of the blue cube",
    "in the starting position the red cube is behind the blue cube",
    "before the episode, the red cube is at the back left corner",
    "set up with the red cube on the green patch",
    "the red cube, starting on the green patch, goes behind the blue cube",
    "move the red cube, which sits on the blue cube, to the green patch",  # the blue cube had been sent to the patch
    "the red cube is on the blue cube, and should end up on the green patch",
    "move the red cube sitting on the blue cube to the green patch",
    "move the red cube from behind the blue cube to the green patch",
    "the red cube goes on the green patch after sitting behind the blue cube",
    "the red cube used to sit on the blue cube",
    "put the red cube on the blue cube and then lift it",
    "put the red cube on the blue cube for a second",
    "the red cube wants to be on the blue cube",
    # counts and distances in notations not read
    "build a tower of 3\u00bd cubes", "put .5 cubes in a row", "2+2 cubes in a row", "a row of three-plus cubes",
    "~3 cubes in a row", "three/four cubes in a row", "make a row of three red cubes - actually four",
    "make a row of three red cubes. Make it four.", "put the red cube one cube left of the blue cube",
    "put the red cube high above the blue cube",
    # an upright row, an order of a row read without one
    "make a vertical row of red, blue and green",
    "put the blue and red cubes on either side of the green cube, vertically",
    "make a row of red, blue and green, in sequence", "make a row of red followed by blue followed by green",
    "make a row of red then blue then green", "make a row red-blue-green", "a row of red, blue and green beginning with red",
    # colours said of a group without which cube has which (five red cubes had been made of "all red but one")
    "a row of five cubes, all red but one", "a row of three cubes of two colours", "a row of five matching cubes",
])
def test_forty_ninth_session_what_a_hostile_helper_found_dropped_is_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("put the red cube to the left and the blue cube to the right of the green cube",
     ["left_of(red,green)", "right_of(blue,green)"]),  # the first had been the table's left region
])
def test_forty_ninth_session_both_sides_of_a_cube_said_last(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text", ["build a tower of red, green and blue in random order",
                                  "stack red, green and blue in some order"])
def test_forty_ninth_session_a_random_order_is_no_order(text):
    assert [type(p).__name__ for p in check_feasibility(parse(text)).goal_predicate().walk()] == ["UnorderedStack"]


@pytest.mark.parametrize("text", [
    # a second hostile helper's (forty-ninth session): a relation after a listed structure (its last cube had taken it)
    "Build a tower of red and blue behind green.", "Stack red and blue behind green.",
    "Make a row of red, blue and yellow next to green.",
    # structures nobody built (made up)
    "Put red on the blue circle.", "Put red in the circle.", "Make a tower as tall as the blue tower.",
    # an exclusion, a colour only or another colour, both cubes on one, a distance
    "Put a cube other than red on blue.", "Build a tower of three cubes. Red and blue only.",
    "Put both red and green on blue.", "Stack two red cubes and a cube of another colour.",
    "Put red two cubes left of blue.", "Put red left of blue by two cubes.",
])
def test_forty_ninth_session_what_a_second_hostile_helper_found_is_refused(text):
    with pytest.raises(BadInput):
        check_feasibility(parse(text))


@pytest.mark.parametrize("text, expected", [
    ("Put the red cube on the blue one and a green one next to it", ["next_to(blue,green)", "stack(blue,red)"]),
    ("Build a 2x2 grid of red cubes", ["grid(2x2:red,red,red,red)"]),
])
def test_forty_ninth_session_a_cube_called_one_and_a_counted_grid_still_read(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text, expected", [
    # a row in one sentence and a cube on a patch in the next: the patch is the cube's (the row had been put on it, and
    # refused as too wide for the patch)
    ("Line up the red and green cubes. Put the yellow cube on the blue patch.", ["line(green,red)", "on_patch(yellow,patch:blue)"]),
    ("Line up the red and green cubes, and put the yellow cube on the blue patch.",
     ["line(green,red)", "on_patch(yellow,patch:blue)"]),
    ("line up two blue cubes on the red patch", ["line(blue,blue)", "on_patch(blue,blue,patch:red)"]),  # one clause: its row's
])
def test_forty_ninth_session_a_patch_said_after_a_row_is_the_next_clause_cube_s(text, expected):
    assert meaning(check_feasibility(parse(text))) == expected


@pytest.mark.parametrize("text", [
    # a start said with a stack, then a goal that relates its cubes: the goal's words are cited past the start's (the
    # order "black left of white" had been uncited, the compile refused as demanding what no word says)
    "Initially, the black cube is stacked on the white cube. Put the black cube to the left of the white cube.",
    "Initially the red cube is on the blue cube. Put the red cube in front of the blue cube.",
])
def test_fiftieth_session_a_goal_after_a_start_stack_cites_its_words(text):
    schema = check_feasibility(parse(text))
    assert schema.initial_state.structures and uncited(schema) == []


def test_fiftieth_session_a_start_under_a_given_heading_is_read():
    """"Given: X is on Y. Task: ..." had been refused as a start not read."""
    assert meaning(check_feasibility(parse("Given: the green cube is on the brown cube. Task: move the green cube onto the cyan patch."))) == [
        "on_patch(green,patch:cyan)", "start:stack(brown,green)"]


@pytest.mark.parametrize("text, expected", [
    # the start read under a misspelt "initially" (it had been read as the goal, and refused)
    ("initialy the green cube is on top of the red cube. take the green cube off and put it on the table",
     ["on_table(green)", "start:stack(red,green)"]),
    ("Intially the red cube is on the blue cube. Put the red cube on the green patch.",
     ["on_patch(red,patch:green)", "start:stack(blue,red)"]),
])
def test_fiftieth_session_a_misspelt_initially_still_says_the_start(text, expected):
    schema = check_feasibility(parse(text))
    assert meaning(schema) == expected and uncited(schema) == []


@pytest.mark.parametrize("text, expected", [
    # a polite request ('mind' had been refused as an action the domain lacks)
    ("Would you mind putting the pink cube behind the cyan one?", ["behind(pink,cyan)"]),
    ("Do you mind stacking the red cube on the blue cube?", ["stack(blue,red)"]),
    # "in that order" after label cubes listed by "labelled" (refused as an order nobody listed)
    ("Line up the cubes labelled M, N and E in that order.", ["line[sequence](M,N,E)"]),
    # "from top" without its article: the list from the top (A had been put at the bottom)
    ("Stack the letter cubes A, B and C alphabetically from top.", ["stack(C,B,A)"]),
])
def test_fifty_first_session_requests_and_orders_said_plainly_are_read(text, expected):
    schema = check_feasibility(parse(text))
    assert meaning(schema) == expected and uncited(schema) == []


@pytest.mark.parametrize("text, word", [
    # piles nobody sorted: which cubes share a pile is not said (piles by colour, of colours nobody named, had been demanded)
    ("Make two piles.", "2 piles"),
    ("Sort the cubes into two piles.", "2 piles"),
    ("Put the cubes in piles.", "several piles"),
    # a patch of its own for each cube: which patch is not said (a red cube on a grey patch had been made up)
    ("Put each cube on its own patch.", "its own patch"),
    ("Put each red cube on its own patch.", "its own patch"),
    # a cube picked by an ordinal and a colour (the parenthesis had been dropped)
    ("Stack the blue cube on the red cube (the second blue).", "the second blue"),
])
def test_fifty_first_session_what_the_words_leave_open_is_refused(text, word):
    with pytest.raises((ParseError, Inexpressible)) as exc:
        check_feasibility(parse(text))
    assert word in str(exc.value)


@pytest.mark.parametrize("text, expected", [
    ("Sort the cubes into piles by colour.", "piles(blue,blue,blue,green,green,green,red,red,red;by=color)"),
    ("Make two piles of three cubes.", "pile(red,red,red); pile(red,red,red)"),
    ("Put the red cube on the red patch.", "on_patch(red,patch:red)"),
])
def test_fifty_first_session_piles_and_patches_said_whole_still_read(text, expected):
    assert "; ".join(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text, expected", [
    # a clause after ", and put" is its own: its cubes are not the stack's (white had been stacked; a hostile helper's)
    ("Stack the red and blue cubes, and put the yellow cube next to the white cube", "next_to(white,yellow); stack(red,blue)"),
    ("Stack green and blue, and put the red cube in the front right", "in_region(red,front_right); stack(green,blue)"),
    # a stack of cubes nobody named takes no colour another clause names (the red cube put beside blue had been stacked)
    ("Stack two cubes. Put the red cube next to the blue cube.", "next_to(blue,red); stack(green,yellow)"),
    # piles: "three each" counts every pile said by colour (a cube each had been made); two piles one per colour are two
    ("Make a pile of red cubes and a pile of blue cubes, three each.", "pile(blue,blue,blue); pile(red,red,red)"),
    ("Sort the cubes into two piles, one for each colour.", "piles(blue,blue,blue,red,red,red;by=color)"),
])
def test_fifty_first_session_a_hostile_helper_s_silent_cases_read_as_said(text, expected):
    assert "; ".join(meaning(check_feasibility(parse(text)))) == expected


@pytest.mark.parametrize("text", [
    "Each cube goes on its own patch.",
    "Put each of the red cubes on its own patch.",
    "Put all cubes on their own patch.",
    "Put the first blue and the second blue on the red patch.",
    "Put the second-blue cube on the red cube",
    # "in that order" with more said after it: the label list is not read as the order (the red cube had been stacked in
    # E's place)
    "Stack the cubes labelled M, N and E in that order next to the red cube",
])
def test_fifty_first_session_a_hostile_helper_s_silent_cases_refused(text):
    with pytest.raises((ParseError, Inexpressible)):
        check_feasibility(parse(text))


def test_fifty_first_session_a_stack_listed_from_the_top_beside_another_clause_keeps_its_order():
    # the stack's clause read apart from ", and put ..." still lists from the top (green had been put at the bottom)
    assert meaning(check_feasibility(parse("Stack green and blue from top to bottom and put the red cube in the front right"))) == [
        "in_region(red,front_right)", "stack(blue,green)"]
