"""Words and clauses: the tokeniser (hyphen-joined words kept apart, dashes as commas) and the
sentence/clause split the reader walks.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from scenewright.core.catalogue import singular


#: Letters of any script, so an accented word ("café", "Stühle") stays one word.
_TOKEN = re.compile(r"\d{2,4}'?s\b|\d+(?:\.\d+)?|[^\W\d_]+(?:['’][^\W\d_]+)?|[.,;:!?()\"“”]|['‘’]|[-–—]")
#: Marks that open or close a quotation; single ones only where no apostrophe can be meant.
_DOUBLE_QUOTES = '"“”'
_SINGLE_QUOTES = "'‘’"


@dataclass
class _Tok:
    text: str  # lowercase
    orig: str
    joined: bool  # hyphen-joined to the previous word ("three-tiered")
    #: Inside quotation marks: the words written on a thing ("a sign reading 'Fresh Fish'"), no things.
    quoted: bool = False


def _tokenise(text: str) -> list[_Tok]:
    toks: list[_Tok] = []
    hyphen = False
    prev_end = -1
    quoting = False
    for m in _TOKEN.finditer(text):
        s = m.group(0)
        if s in _SINGLE_QUOTES or s in _DOUBLE_QUOTES:
            before = text[m.start() - 1] if m.start() else " "
            after = text[m.end()] if m.end() < len(text) else " "
            plural_owner = s in _SINGLE_QUOTES and toks and m.start() == prev_end and toks[-1].text.endswith("s")
            if plural_owner and not quoting and not after.isalnum() and toks[-1].text[:1].isalpha():
                # "the judges' stand" reads as "the judge's stand": a possessive, as the reader knows them
                toks[-1].text = singular(toks[-1].text) + "'s"
                toks[-1].orig += s
                prev_end = m.end()
                continue
            if not quoting and (before.isspace() or before == "(") and after.isalnum():
                quoting = True  # "a sign reading 'Open'": opens; "the dogs' bowls" does not
            elif quoting and not before.isspace():
                quoting = False
            if s in _SINGLE_QUOTES:
                prev_end = m.end()
                continue
            s = '"'
        if s in "-–" and m.start() == prev_end:
            hyphen = True
            prev_end = m.end()
            continue
        if s in "—–-":
            s = ","
        joined = hyphen and m.start() == prev_end
        hyphen = False
        prev_end = m.end()
        if joined and s.lower() == "shaped" and len(toks[-1].text) > 1 and toks[-1].text.isalpha():
            continue  # "a dome-shaped habitat" is a dome habitat ("an L-shaped sofa" keeps its letter)
        toks.append(_Tok(s.lower().replace("’", "'"), s, joined, quoting and s != '"'))
        if s in (".", "!", "?"):
            quoting = False  # a quotation nobody closed ends with its sentence
        if len(toks) > 2 and [t.text for t in toks[-3:-1]] in (["on", "board"], ["on", "deck"]) and not (
            toks[-1].text[:1].isalpha() and toks[-1].text not in _AFTER_ABOARD
        ):  # "six tourists on deck", "with a crew on board": aboard, no board nor deck of their own
            toks[-3:-1] = [_Tok("aboard", f"{toks[-3].orig} {toks[-2].orig}", toks[-3].joined, toks[-3].quoted)]
    _quote_capitals(toks)
    return toks


def _quote_capitals(toks: list[_Tok]) -> None:
    """Two or more words in capitals in a row are writing, as if quoted ("a sign spells out
    ATTACK OF THE IGUANA": no iguana)."""
    k = 0
    while k < len(toks):
        j = k
        while j < len(toks) and _capitals(toks[j].orig, j == k):
            j += 1
        for t in toks[k:j] if j - k >= 2 else ():
            t.quoted = True
        k = max(j, k + 1)


def _capitals(word: str, first: bool) -> bool:
    """A word in capitals; a one-letter one ("A", "I") only inside a run, never opening it ("A TV stands")."""
    return word.isalpha() and word.isupper() and (len(word) > 1 or not first and word in ("A", "I"))


#: Words that may follow "on board" or "on deck" meaning aboard the vessel named before ("on deck
#: and ...", "on board while ..."); any other word names a thing ("on deck chairs", "on board games").
_AFTER_ABOARD = {"and", "while", "as", "with", "each", "watching", "waving", "holding", "looking"}


_CLAUSE_BREAK = {",", ";", ":", "(", ")", '"'}
_CLAUSE_WORDS = {"while", "whereas", "where", "whilst", "although", "though"}
_SENTENCE_END = {".", "!", "?"}


def _split(toks: list[_Tok]) -> list[list[tuple[int, int]]]:
    """Sentences as lists of clauses, each a (start, end) token span."""
    sentences: list[list[tuple[int, int]]] = []
    clauses: list[tuple[int, int]] = []
    start = 0
    for i, t in enumerate(toks + [_Tok(".", ".", False)]):
        if t.text in _SENTENCE_END or t.text in _CLAUSE_BREAK or t.text in _CLAUSE_WORDS:
            if i > start:
                clauses.append((start, i))
            start = i + 1
            if t.text in _SENTENCE_END and clauses:
                sentences.append(clauses)
                clauses = []
    return sentences
