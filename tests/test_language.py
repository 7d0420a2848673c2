"""The front end's lexicon, clause reader and mention accounting (rpg.schema.lexicon,
rpg.schema.clauses, rpg.schema.accounting). Language written by people is tested in
test_corpus.py; these pin down the mechanisms."""

import pytest

from rpg.schema.builtin import ParseError, normalize, parse
from rpg.schema.meaning import meaning


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
])
def test_reads(text, expected):
    assert meaning(parse(text)) == sorted(expected)


@pytest.mark.parametrize("text,named", [
    ("build one tower of red and one of green", "2 towers"),
    ("build a tower of 5 and a tower of 2", "tower of 5"),
    ("put three green blocks right of the red ones", "3 green"),
    ("a column of two in each corner", "each corner"),
    ("put red on blue and blue on red", "contradict"),
    ("push the red block until it is sitting on the target", "until"),
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
    from rpg.schema.builtin import COLOR_RE, _canon_color

    schema = parse("stack the red block on the blue block")
    with pytest.raises(UnaccountedMention, match="left of"):
        account("stack the red block on the blue block left of the green block", schema, COLOR_RE, _canon_color)
    record = account("put the red block left of the blue block", parse("put the red block left of the blue block"),
                     COLOR_RE, _canon_color)
    assert {"mention": "left of", "kind": "relation", "consumed_by": "left_of"} in record
