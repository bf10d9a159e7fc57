"""The report's references: every source its text cites is listed, and every listed source is cited.

"Its text" is everything a reader of the report can meet: the templates, every message of the package
(the string literals of assess/, docstrings left out: they are for developers, and cite what the code
implements), and a rendered report. A citation is a name with a year ("Housner 1963", "Konstantinidis &
Makris (2010)"), a name's method ("Housner's", "Mavroeidis–Papageorgiou"), or a standard ("ASCE 7-22",
"FEMA E-74", "ASCE 41-17").
"""
from __future__ import annotations

import ast
import html as html_module
import re
from pathlib import Path

import pytest

from assess.report import render_html
from assess.report.references import REFERENCES, reference_rows
from tests.report.test_report import make_result

ROOT = Path(__file__).resolve().parents[2]

NAME = r"[A-Z][a-zà-ÿ]+(?:[- ][A-Z][a-zà-ÿ]+)?"  # Housner, Der Kiureghian, Papageorgiou
#: "Konstantinidis & Makris (2010)", "Dabaghi & Der Kiureghian 2017", "Makris and Roussos, 2000"
AUTHORS_YEAR = re.compile(rf"\b({NAME}(?:(?:, | & | and ){NAME})*)(?: et al\.)?,? \(?((?:19|20)\d\d)\b")
#: "Housner's", "Newmark's", "Mavroeidis–Papageorgiou", "Moreau–Jean"
EPONYM = re.compile(rf"\b({NAME})'s\b|\b({NAME})–({NAME})\b")
STANDARD = re.compile(r"\b(ASCE(?:/SEI)? (?:7|41)(?:-\d\d)?|FEMA [EP]-\d+|FEMA \d{3}|ACI \d{3}(?:-\d\d)?)\b")

#: Capitalised words before a year or an "'s" that name no source: earthquakes and places (Loma Prieta
#: 1989), months, software and file formats. A word here is never a reference's author.
NOT_SOURCES = {"Loma Prieta", "Prieta", "Excel", "Python", "Windows", "January", "November", "December",
               "Working Model", "Model", "Table", "Figure", "Fig", "Section", "Dask"}


def _string_literals(path: Path):
    """The string constants of a module that are not docstrings."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docstrings = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                docstrings.add(id(first.value))
    return [node.value for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings]


def _report_text() -> str:
    html = render_html(make_result(simulated=True))
    html = re.sub(r"<script.*?</script>|<style.*?</style>", "", html, flags=re.S)
    html = html.split('<section id="references">')[0]  # the list itself is not a citation of itself
    return html_module.unescape(re.sub(r"<[^>]+>", "", html))


def texts() -> dict[str, str]:
    """Every text a reader meets, by where it is."""
    out = {str(p.relative_to(ROOT)): p.read_text(encoding="utf-8") for p in sorted((ROOT / "templates").glob("*.j2"))
           if p.name != "_references.html.j2"}
    for path in sorted((ROOT / "assess").rglob("*.py")):
        if path.name == "references.py":
            continue
        literals = _string_literals(path)
        if literals:
            out[str(path.relative_to(ROOT))] = "\n".join(literals)
    out["a rendered report"] = _report_text()
    return {where: html_module.unescape(text).replace("&amp;", "&") for where, text in out.items()}


def citations(text: str) -> set[tuple[tuple[str, ...], str]]:
    """The citations in ``text``: (names, year) with year '' for an eponym, ((designation,), '') for a
    standard."""
    found = set()
    for match in AUTHORS_YEAR.finditer(text):
        names = tuple(n for n in re.split(r", | & | and ", match.group(1)) if n not in NOT_SOURCES)
        if names:
            found.add((names, match.group(2)))
    for match in EPONYM.finditer(text):
        names = tuple(n for n in match.groups() if n and n not in NOT_SOURCES)
        if names:
            found.add((names, ""))
    for match in STANDARD.finditer(text):
        found.add(((match.group(1).replace("ASCE/SEI", "ASCE"),), ""))
    return found


def listed(names: tuple[str, ...], year: str) -> bool:
    """Whether one reference is by all of ``names`` (of that year, if one is given), or is that standard; a
    method named after two people without a year (Moreau–Jean) is listed when each has a reference."""
    if not year and len(names) > 1:
        return all(listed((name,), "") for name in names)
    for reference in REFERENCES:
        head = reference.text.split("(")[0]  # the authors (or the standard), before the year
        if year and reference.year and year != reference.year:
            continue
        if all(re.search(rf"\b{re.escape(name)}\b", head) for name in names):
            return True
        designation = names[0]
        if len(names) == 1 and designation.startswith(("ASCE", "FEMA", "ACI")) and (
                reference.cited_as == designation or reference.cited_as.startswith(designation + "-")):
            return True  # "ASCE 41" (any edition) is ASCE 41-17; "ASCE 7" is 7-16 and 7-22
    return False


@pytest.fixture(scope="module")
def all_texts():
    return texts()


def test_the_citation_finder_finds_what_it_must():
    text = ("after Dabaghi & Der Kiureghian 2017; Konstantinidis & Makris (2010), eq. 21; Housner's e; a "
            "Mavroeidis–Papageorgiou pulse; ASCE 7-22 §13.3; ASCE/SEI 41-17; FEMA E-74 (2012); Loma Prieta (1989)")
    assert citations(text) == {(("Dabaghi", "Der Kiureghian"), "2017"), (("Konstantinidis", "Makris"), "2010"),
                               (("Housner",), ""), (("Mavroeidis", "Papageorgiou"), ""), (("ASCE 7-22",), ""),
                               (("ASCE 41-17",), ""), (("FEMA E-74",), "")}
    assert not listed(("Smith",), "1999") and not listed(("Housner",), "1970")
    assert listed(("Der Kiureghian", "Dabaghi"), "2017") and listed(("ASCE 7",), "")


def test_every_source_the_text_cites_is_in_the_references(all_texts):
    missing = sorted({f"{' & '.join(names)} {year}".strip() + f"  ({where})"
                      for where, text in all_texts.items() for names, year in citations(text)
                      if not listed(names, year)})
    assert not missing, "cited but not in assess/report/references.py:\n" + "\n".join(missing)


def test_every_reference_is_cited_somewhere(all_texts):
    cited = set().union(*(citations(text) for text in all_texts.values()))
    uncited = []
    for reference in REFERENCES:
        names = tuple(reference.cited_as.split(" & "))
        hit = any(c_names == (reference.cited_as,) or (set(names) <= set(c_names) and c_year in ("", reference.year))
                  or (reference.cited_as.startswith(c_names[0] + "-") and len(c_names) == 1)
                  for c_names, c_year in cited)
        if not hit:
            uncited.append(reference.cited_as)
    assert not uncited, f"listed but cited nowhere: {uncited}"


def test_the_sources_the_report_must_carry_are_listed():
    """The sources the text is known to rest on (issue 19), whatever the text says today."""
    for names, year in [(("Konstantinidis", "Makris"), "2010"), (("Housner",), "1963"), (("Shenton",), "1996"),
                        (("Makris", "Roussos"), "2000"), (("Zhang", "Makris"), "2001"),
                        (("Dabaghi", "Der Kiureghian"), "2017"), (("Rezaeian", "Der Kiureghian"), "2008"),
                        (("Baker",), "2015"), (("ASCE 7-16",), ""), (("ASCE 7-22",), ""), (("FEMA E-74",), ""),
                        (("ASCE 41-17",), "")]:
        assert listed(names, year), (names, year)


def test_the_report_lists_them_all_once_in_order():
    html = render_html(make_result())
    listed_items = re.findall(r"<li>(.*?)</li>", html.split('<ol class="references">')[1].split("</ol>")[0], re.S)
    assert len(listed_items) == len(REFERENCES) == len({r.text for r in REFERENCES})
    assert [html_module.unescape(item).split(" doi:")[0] for item in listed_items] == [r["text"] for r in reference_rows()]
    firsts = [r["text"].split(",")[0].split(" ")[0].lower() for r in reference_rows()]
    assert firsts == sorted(firsts)
