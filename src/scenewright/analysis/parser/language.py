"""Is the text English? The offline reader's rules are English rules.

A French or German description would otherwise come out as a scene of the few words that
happen to be English too ("une table en bois avec deux chaises" → one table), with exit 0.
English prose, even a short list of things, carries its small words (articles, prepositions,
"and", counts) or nouns the catalogue knows; other languages carry few of either.
"""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache

from scenewright.core.catalogue import load_catalogue, singular, words
from scenewright.analysis.parser.vocabulary import load_vocabulary
from scenewright.errors import InputError

#: Closed-class English words that almost every description uses.
_ENGLISH = frozenset(
    "a an the and or with of on in at to by from near beside behind above under over into onto "
    "next between around is are there it its them this that these those some several many few "
    "each every one two three four five six seven eight nine ten twelve has have stands sits "
    "small large big tall little old new wooden red blue green white black grey gray brown "
    "yellow left right front back middle corner against along inside for stand sit lies hang "
    "hangs while where which room scene".split()
)
#: Small words of the languages people most often write in instead (French, Spanish, German,
#: Italian, Portuguese, Dutch) that are no English words.
_FOREIGN = frozenset(
    "le la les un une des et avec dans sur sous du au aux est sont el los las y con una del por para "
    "junto der die das und mit ein eine einer einem auf im neben dem den ist il lo gli della di nel "
    "sul con uno os um uma com na ao ou het een met op naast bij".split()
)
_WORD = re.compile(r"[^\W\d_]+")
#: Below this many words a text is judged only by foreign small words ("Cyberpunk ramen bar").
SHORT_TEXT = 6
#: Fewer known words than this share of the text's words means another language.
MIN_KNOWN_SHARE = 0.3
#: Shortest text judged: a name or two ("Treehouse", "Zen garden") is left alone.
MIN_WORDS = 3

OTHER_LANGUAGE = (
    "the offline reader reads English, and this text looks like another language ({sample}); "
    "write the description in English, or let a vision-language model read it: "
    "--vlm openai:MODEL (e.g. --vlm openai:o3 with OPENAI_API_KEY set, or --base-url for a local server)"
)


@lru_cache(maxsize=1)
def known_words() -> frozenset[str]:
    """English words the reader knows: its small words and every catalogue and vocabulary noun."""
    known = set(_ENGLISH)
    for category in load_catalogue().values():
        for phrase in category.phrases:
            known.update(words(phrase))
    vocabulary = load_vocabulary()
    for phrase in vocabulary.entries:
        known.update(phrase)
    for word in (*vocabulary.not_things, *vocabulary.adjectives):
        known.update(words(word))
    return frozenset(known - _FOREIGN)


def check_english(text: str) -> None:
    """Raise :class:`InputError` when ``text`` is not English (see the module's note)."""
    found = _WORD.findall(text.lower())
    letters = [ch for ch in text if ch.isalpha()]
    other_script = sum(1 for ch in letters if not unicodedata.name(ch, "").startswith("LATIN"))
    if other_script * 2 > len(letters):  # Chinese, Russian, Greek...: no English rule can read it
        raise InputError(OTHER_LANGUAGE.format(sample=repr(text.strip()[:24])))
    if len(found) < MIN_WORDS:
        return
    known = known_words()
    share = sum(1 for w in found if w in known or singular(w) in known) / len(found)
    small = any(w in _ENGLISH for w in found)
    foreign = sum(1 for w in found if w in _FOREIGN) / len(found)
    long_text = len(found) >= SHORT_TEXT
    if foreign >= 0.15 or (long_text and (share < MIN_KNOWN_SHARE or not small)):
        unknown = [w for w in found if w not in known][:4]
        raise InputError(OTHER_LANGUAGE.format(sample=", ".join(repr(w) for w in unknown)))
