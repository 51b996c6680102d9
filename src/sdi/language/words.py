"""Word classes for honest accounting: which words of a command may go unused, which may not.

Every word of a command is either used by the reading or reported. A word left unused is
**material** — it makes the plan `partial` instead of `success` — when it is a number, a
negation, a word the Specifier knows the meaning of (a shape, size, dimension, region or
relation word), or any other content word (noun, verb, adjective, adverb) that is not in the
lists of harmless words below. Harmless words are function words and fillers ("please",
"build", "the"), words the grammar reads from context without marking them ("hollow",
"corner", "each"), and words with no bearing on geometry ("nice", "demo", "quickly").
"""

from __future__ import annotations

from sdi.spec import lexicon as lx
from sdi.spec.numbers import QUANTITY_WORDS, SCALES, TENS, UNITS


def _words(text: str) -> frozenset[str]:
    return frozenset(text.split())


NEGATIONS = frozenset({"not", "n't", "no", "never", "without", "nor", "neither", "dont", "cannot"})

# Words the grammar consults by context without marking them used (idioms, heads of
# compounds, words that select a reading).
CONSULTED = _words(
    """
    top each other along base bases stem stems bar bars across both arms something like sized
    side sides by packed
    tightly together height around empty hollow space inside rectangular square per corner
    corners rising fill area densely joined next it separate table lay out into dense
    possible than as cube cubes block blocks part parts piece pieces brick bricks unit units
    box boxes cases carton cartons one ones single total overall level levels layer layers row rows
    shape shaped
    form formed forming pattern arrangement configuration setup style sort kind type version
    copy edge edges end ends leg legs roof pillars pillar support supports foot feet apart
    spaced spacing gap gaps above over solid filled full compact tight close open centre
    center middle robot each every all with of at on in to from into onto upon atop up down
    x y z axis direction wise diagonal diagonally degrees degree deg rotated turned quarter
    sideways lengthwise crosswise away towards toward cm mm m metre metres meter meters
    centimetre centimetres centimeter centimeters millimetre millimetres millimeter
    millimeters inside interior hole opening cavity void courtyard beam beams plank planks
    bar bars girder girders lintel lintels stacked stacking piled pile stack footprint
    """
)

# Words that carry no geometric meaning: never material.
HARMLESS = _words(
    """
    qty qnty ea pcs ext external o/a overall
    a an the this that these those some any please kindly can could would will shall should
    must may might you your i me my we us our let lets want wanted need needs needed like
    love just now go ahead hey hi hello robot robots okay ok thanks thank cheers really very
    quite pretty rather nice neat cool beautiful good great lovely fine simple basic plain
    maybe perhaps kind sort type style looking look looks something thing things structure
    structures model design figure build building builds make making makes create creating
    construct constructing assemble assembling erect put putting place placing set setting
    produce generate give get do does done doing up out down together using use used from
    made consisting composed comprising built arranged arrange lay laying laid position
    positioned located standing stand stands stood sitting sit sat resting rest is are be been being
    was were am it its it's there here then also so and or but if for with of in on at by as
    into onto to about approximately roughly nearly almost only exactly overall total
    altogether area zone region workspace cell spot location table demo demonstration test
    testing trial customer client visitors visitor show showcase display today tomorrow
    quickly quick slowly carefully careful fast again first firstly second next finally
    afterwards after lastly last start begin begins starting new fresh whole entire some
    what how which who where when while though although because since so, such own same
    identical matching similar another additional further other more please! alright right
    sure yes yeah well guys folks team assistant system sdi go add adding insert finish
    complete continue repeat begin keep probably placed situated sited simple thats id isnt
    its im ive youre whats lets pls plz ty thx
    umm um uh er hmm basically actually honestly hand irb irb120 irb1600 straight anywhere
    measuring measures measured outside outer external climbing ascending going deck length
    width height depth equal equally even evenly same each definitely certainly surely
    absolutely precisely have has having had period comma stop u ur story stuff point work
    working surface bench heights lengths widths sizes plus tidy task running runs actually
    sorry oops wait req fyi thx asap kindly ta lonely sturdy sign slide visual deck mock
    mockup meanwhile anyway anyways besides btw otherwise replicate reproduce stage staged
    deliver fetch prepare approx approximate exact dimension dimensions better best
    proper plonk plonked plonking pop popped somewhere finished result resulting end product
    completely totally fully entirely rebuild rebuilding rebuilt redo remake replace replacing
    replacement fallen collapsed segment shim shims case plumb rests sits hold holds run
    fr ngl tbh lowkey highkey thingy thingie bc cuz coz lil bruh fam reckon reckons lovely ta cheers
    footprint
    properly proper
    """
)

# Where a word may be corrected to (content words the Specifier knows).
CORRECTABLE = frozenset(
    set(lx.SHAPE_WORDS)
    | set(lx.SIZE_WORDS)
    | set(lx.DIMENSION_WORDS)
    | set(lx.REGION_WORDS)
    | lx.LEVEL_WORDS
    | lx.STEP_WORDS
    | lx.SPAN_WORDS
    | lx.PART_WORDS
    | set(UNITS)
    | set(TENS)
    | {
        "stacked", "surround", "surrounded", "surrounding", "around", "beside", "between",
        "joined", "connected", "connecting", "joining", "inside", "centimetres", "centimeters",
        "millimetres", "millimeters", "corner", "pyramid", "staircase", "enclosure",
        "column", "bridge", "tower", "castle", "canopy", "please", "build", "place", "the",
        "shape", "shaped", "with", "make", "put", "and", "high", "long", "wide", "cubes",
        "next", "behind", "front", "stack", "apart", "away", "arms", "base", "legs", "steps",
    }
)  # fmt: skip

VOCABULARY = frozenset(
    CORRECTABLE
    | CONSULTED
    | HARMLESS
    | NEGATIONS
    | lx.FILLER
    | set(QUANTITY_WORDS)
    | set(SCALES)
    | set(lx.UNITS_M)
)

# Words that change a size, a count or a direction wherever the parse attaches them ("the right
# one twice as tall", "nine minus four", "going down into the table"): left unused, they are
# material even when the parse hangs them on the chatter.
SIGNIFICANT = _words(
    """
    twice thrice double doubled triple tripled quadruple half halve halved minus fewer less
    times taller shorter higher lower bigger smaller wider narrower longer deeper shallower
    thicker thinner tallest shortest highest lowest biggest smallest widest longest
    below underneath beneath floating hanging hovering suspended upside inverted
    sunk sunken buried turn rotate twist flip mirror mirrored reflect reflected reflection
    checkerboard chessboard alternate alternating facing
    skip skipping skipped omit omitting omitted except excepting excluding exclude excluded
    missing instead demolish demolished destroy destroyed dismantle dismantled
    topple toppled scrap scrapped dozen dozens quit remove removed removing delete deleted forget
    cancel cancelled tear split splitting lift lifted ditch
    extend extends extended extending lengthen lengthened shorten shortened widen widened
    enlarge enlarged expand expanded supersede supersedes superseded
    """
)

MATERIAL_POS = frozenset({"NOUN", "PROPN", "VERB", "ADJ", "ADV", "NUM", "X", "INTJ"})


def is_material(word: str, pos: str | None) -> bool:
    """An unused word that makes the reading incomplete (see the module doc)."""
    w = word.lower()
    if w in NEGATIONS or w in SIGNIFICANT:
        return True
    if w[:1].isdigit() or (w[:1] == "-" and w[1:2].isdigit()):
        return True
    if w in HARMLESS or w in CONSULTED or w in lx.FILLER:
        return False
    if not any(c.isalpha() for c in w):
        return False
    if w in CORRECTABLE or w in QUANTITY_WORDS:
        return True
    return pos is None or pos in MATERIAL_POS
