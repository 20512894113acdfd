"""A class's variants exported to the formats schools use: Moodle XML, QTI 1.2 (Canvas),
PDF through Typst, and Markdown and HTML, one file per student.

:func:`build_class` draws every student's variant of every chosen exercise once (the seeds
of :func:`~mech.exercises._sheet.student_seeds`); the writers turn that into files:

- :func:`write_moodle`: one question per exercise and student, in a category per exercise
  (so that a quiz's random question draws one variant per student), numerical answers with
  the tolerance ``check`` uses and units, the variant's figure embedded as a base64
  ``<file>``, and the worked solution as general feedback;
- :func:`write_qti`: a zip with ``imsmanifest.xml`` and a QTI 1.2 assessment whose sections
  (one per exercise, drawing one item) hold an item per student variant, figures as files;
- :func:`write_pdf`: Typst sources compiled to a sheet and a key per student and a class
  list;
- :func:`write_markdown`: a sheet and a key per student in Markdown and HTML.

Matplotlib, Typst and the XML writer are imported inside the functions.
"""

from __future__ import annotations

import base64
import csv
import html
import math
from dataclasses import dataclass
from pathlib import Path

__all__ = ["Item", "Student", "build_class", "write_class_list", "write_markdown", "write_moodle", "write_pdf",
           "write_qti"]


@dataclass(frozen=True)
class Item:
    """One student's variant of one exercise: givens, solution, answers and figure (PNG)."""

    number: str
    title: str
    statement: str
    params: dict
    solution: object
    quantities: tuple
    figure: bytes


@dataclass(frozen=True)
class Student:
    """A student of the class: their number (1, 2, ...), seed and variants."""

    index: int
    seed: int
    items: tuple

    @property
    def label(self):
        return f"student_{self.index:02d}"


def build_class(numbers, *, students=30, seed=0, figures=True):
    """Draw and solve every student's variant of the exercises ``numbers``; a list of
    `Student`. With ``figures=False`` the figures are left empty (quicker, for keys)."""
    from mech.exercises import get
    from mech.exercises._figures import figure_png
    from mech.exercises._sheet import answer_quantities, solved_variant, student_seeds

    if isinstance(numbers, str):
        numbers = (numbers,)
    exercises = [get(n) for n in numbers]
    if not exercises:
        raise ValueError("Expected `numbers` to name at least one exercise, got none")
    out = []
    for k, s in enumerate(student_seeds(seed, students), start=1):
        items = []
        for ex in exercises:
            params, solution = solved_variant(ex, s)
            items.append(Item(ex.number, ex.title, ex.statement_text(params), params, solution,
                              answer_quantities(solution), figure_png(ex.number, params) if figures else b""))
        out.append(Student(k, s, tuple(items)))
    return out


def _fmt(x):
    return f"{x:.6g}"


def _unit_text(unit):
    return {"deg": "°", "": ""}.get(unit, unit)


def write_class_list(students, path):
    """A CSV of the class: student number, label and seed (what ``check`` needs)."""
    with Path(path).open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "label", "seed"])
        for st in students:
            w.writerow([st.index, st.label, st.seed])


# ----------------------------------------------------------------------------- Markdown / HTML
def _answer_lines(item):
    return [f"- `{q.key}`: {q.what}" + (f" ({q.unit})" if q.unit else "") for q in item.quantities]


def write_markdown(students, out, *, title="Problem sheet", html_too=True):
    """Write ``student_NN.md`` and ``student_NN_key.md`` (and ``.html`` with the figures
    embedded) per student into ``out``, the figures as PNG files in ``out/figures``."""
    from mech.exercises._sheet import markdown_to_html

    out = Path(out)
    (out / "figures").mkdir(parents=True, exist_ok=True)
    written = []
    for st in students:
        sheet = [f"# {title}: {st.label} (seed {st.seed})", ""]
        key = [f"# {title}: answer key, {st.label} (seed {st.seed})", ""]
        for it in st.items:
            fig = f"figures/{st.label}_{it.number}.png"
            if it.figure:
                (out / fig).write_bytes(it.figure)
            sheet += [f"## Exercise {it.number}: {it.title}", "", it.statement, ""]
            if it.figure:
                sheet += [f"![Figure of exercise {it.number}]({fig})", ""]
            sheet += ["Answer with these keys:", ""] + _answer_lines(it) + [""]
            key += [f"## Exercise {it.number}", "", "| key | asks for | value |", "|---|---|---|"]
            key += [f"| `{q.key}` | {q.what} | {_fmt(q.value)} {q.unit} |" for q in it.quantities]
            key += ["", it.solution.as_markdown(), ""]
        for name, lines in ((f"{st.label}.md", sheet), (f"{st.label}_key.md", key)):
            text = "\n".join(lines).rstrip() + "\n"
            (out / name).write_text(text, encoding="utf-8")
            written.append(out / name)
            if html_too:
                page = markdown_to_html(text, title=lines[0][2:])
                for it in st.items:              # a page that stands alone: the figures inline
                    fig = f"figures/{st.label}_{it.number}.png"
                    if it.figure:
                        page = page.replace(f'src="{fig}"', 'src="data:image/png;base64,'
                                            + base64.b64encode(it.figure).decode("ascii") + '"')
                (out / name.replace(".md", ".html")).write_text(page, encoding="utf-8")
                written.append(out / name.replace(".md", ".html"))
    write_class_list(students, out / "class_list.csv")
    return written


# ----------------------------------------------------------------------------- Moodle XML
def _solution_html(item):
    from mech.exercises._sheet import markdown_to_html

    import re

    page = markdown_to_html(item.solution.as_markdown(), title="")
    body = page.split("<body>\n", 1)[1].rsplit("</body>", 1)[0]
    # the LMS's MathJax filter reads \( ... \): the formulas typeset there
    body = re.sub(r'<span class="math inline">(.*?)</span>', r"\\(\1\\)", body)
    return re.sub(r'<div class="math block">(.*?)</div>', r"\\[\1\\]", body, flags=re.S)


def write_moodle(students, path, *, rtol=0.01, atol=0.01, category="mech"):
    """Write a Moodle XML question bank to ``path``: a category per exercise
    (``$course$/top/CATEGORY/Exercise N``) holding one question per student variant.

    A question with one answer is of type ``numerical`` (answer, tolerance, units); one
    with several is ``cloze``, each answer a ``{1:NUMERICAL:=value:tolerance}`` followed by
    its unit. The tolerance is ``check``'s, ``rtol * |value| + atol``. Returns the tree."""
    import xml.etree.ElementTree as ET

    root = ET.Element("quiz")

    def text_el(parent, tag, text, fmt=None, **attrs):
        el = ET.SubElement(parent, tag, **({"format": fmt} if fmt else {}), **attrs)
        ET.SubElement(el, "text").text = text
        return el

    numbers = [it.number for it in students[0].items] if students else []
    for j, number in enumerate(numbers):
        q = ET.SubElement(root, "question", type="category")
        text_el(q, "category", f"$course$/top/{category}/Exercise {number}")
        for st in students:
            it = st.items[j]
            single = len(it.quantities) == 1
            q = ET.SubElement(root, "question", type="numerical" if single else "cloze")
            text_el(q, "name", f"Exercise {it.number}, variant {st.seed}")
            fig = f"exercise_{it.number}_{st.seed}.png"
            body = [f"<p>{html.escape(it.statement)}</p>",
                    f'<p><img src="@@PLUGINFILE@@/{fig}" alt="Figure of exercise {it.number}"></p>']
            if single:
                qq = it.quantities[0]
                body.append(f"<p>{html.escape(qq.what)} (<code>{qq.key}</code>)"
                            + (f", in {html.escape(qq.unit)}" if qq.unit else "") + ".</p>")
            else:
                body.append("<ul>")
                for qq in it.quantities:
                    body.append(f"<li>{html.escape(qq.what)} (<code>{qq.key}</code>): "
                                f"{{1:NUMERICAL:={_fmt(qq.value)}:{qq.tolerance(rtol, atol):.6g}}} "
                                f"{html.escape(_unit_text(qq.unit))}</li>")
                body.append("</ul>")
            qt = text_el(q, "questiontext", "\n".join(body), "html")
            f = ET.SubElement(qt, "file", name=fig, path="/", encoding="base64")
            f.text = base64.b64encode(it.figure).decode("ascii")
            text_el(q, "generalfeedback", _solution_html(it), "html")
            ET.SubElement(q, "defaultgrade").text = str(len(it.quantities))
            ET.SubElement(q, "penalty").text = "0.3333333"
            ET.SubElement(q, "hidden").text = "0"
            if single:
                qq = it.quantities[0]
                a = text_el(q, "answer", _fmt(qq.value), "moodle_auto_format", fraction="100")
                ET.SubElement(a, "tolerance").text = f"{qq.tolerance(rtol, atol):.6g}"
                text_el(a, "feedback", "", "html")
                if qq.unit:                              # a ratio or an efficiency has none
                    units = ET.SubElement(q, "units")
                    u = ET.SubElement(units, "unit")
                    ET.SubElement(u, "multiplier").text = "1"
                    ET.SubElement(u, "unit_name").text = qq.unit
                ET.SubElement(q, "unitgradingtype").text = "0"      # a missing unit costs nothing
                ET.SubElement(q, "unitpenalty").text = "0.1000000"
                ET.SubElement(q, "showunits").text = "3"            # units shown in the text only
                ET.SubElement(q, "unitsleft").text = "0"
    tree = ET.ElementTree(root)
    ET.indent(tree)
    tree.write(path, encoding="utf-8", xml_declaration=True)
    return tree


# ----------------------------------------------------------------------------- QTI 1.2
def write_qti(students, path, *, rtol=0.01, atol=0.01, title="mech exercises"):
    """Write a QTI 1.2 zip for Canvas to ``path``: ``imsmanifest.xml``, the assessment
    ``mech_quiz/mech_quiz.xml`` (a section per exercise that draws one item, an item per
    student variant with a ``response_num`` per answer scored within the tolerance) and the
    figures as files that the items' HTML refers to."""
    import xml.etree.ElementTree as ET
    import zipfile

    quiz = "mech_quiz"
    qroot = ET.Element("questestinterop")
    assessment = ET.SubElement(qroot, "assessment", ident=quiz, title=title)
    files = {}
    numbers = [it.number for it in students[0].items] if students else []
    for j, number in enumerate(numbers):
        section = ET.SubElement(assessment, "section", ident=f"section_{number}", title=f"Exercise {number}")
        sel = ET.SubElement(ET.SubElement(section, "selection_ordering"), "selection")
        ET.SubElement(sel, "selection_number").text = "1"          # one variant per student
        for st in students:
            it = st.items[j]
            ident = f"item_{number}_{st.seed}"
            item = ET.SubElement(section, "item", ident=ident, title=f"Exercise {number}, variant {st.seed}")
            meta = ET.SubElement(ET.SubElement(item, "itemmetadata"), "qtimetadata")
            for label, entry in (("question_type", "numerical_question" if len(it.quantities) == 1
                                  else "fill_in_multiple_blanks_question"),
                                 ("points_possible", str(len(it.quantities)))):
                field = ET.SubElement(meta, "qtimetadatafield")
                ET.SubElement(field, "fieldlabel").text = label
                ET.SubElement(field, "fieldentry").text = entry
            fig = f"{quiz}/figures/{ident}.png"
            files[fig] = it.figure
            pres = ET.SubElement(item, "presentation")
            mat = ET.SubElement(ET.SubElement(pres, "material"), "mattext", texttype="text/html")
            mat.text = (f"<p>{html.escape(it.statement)}</p><p><img src=\"figures/{ident}.png\" "
                        f"alt=\"Figure of exercise {number}\"></p>")
            proc = ET.SubElement(item, "resprocessing")
            outcomes = ET.SubElement(proc, "outcomes")
            ET.SubElement(outcomes, "decvar", maxvalue=str(len(it.quantities)), minvalue="0", varname="SCORE",
                          vartype="Decimal")
            for qq in it.quantities:
                rid = f"response_{qq.key}"
                label = ET.SubElement(ET.SubElement(pres, "material"), "mattext", texttype="text/plain")
                label.text = f"{qq.what} ({qq.key})" + (f", in {qq.unit}" if qq.unit else "")
                resp = ET.SubElement(pres, "response_num", ident=rid, rcardinality="Single", numtype="Decimal")
                ET.SubElement(resp, "render_fib", fibtype="Decimal")
                tol = qq.tolerance(rtol, atol)
                cond = ET.SubElement(proc, "respcondition", title=qq.key)
                var = ET.SubElement(cond, "conditionvar")
                ET.SubElement(var, "vargte", respident=rid).text = _fmt(qq.value - tol)
                ET.SubElement(var, "varlte", respident=rid).text = _fmt(qq.value + tol)
                ET.SubElement(cond, "setvar", action="Add", varname="SCORE").text = "1"
            fb = ET.SubElement(item, "itemfeedback", ident=f"{ident}_solution")
            fm = ET.SubElement(ET.SubElement(ET.SubElement(fb, "flow_mat"), "material"), "mattext",
                               texttype="text/html")
            fm.text = _solution_html(it)
    ns = "http://www.imsglobal.org/xsd/imscp_v1p1"
    manifest = ET.Element("manifest", identifier=f"{quiz}_manifest", xmlns=ns)
    md = ET.SubElement(manifest, "metadata")
    ET.SubElement(md, "schema").text = "IMS Content"
    ET.SubElement(md, "schemaversion").text = "1.1.3"
    ET.SubElement(manifest, "organizations")
    resources = ET.SubElement(manifest, "resources")
    res = ET.SubElement(resources, "resource", identifier=quiz, type="imsqti_xmlv1p2")
    ET.SubElement(res, "file", href=f"{quiz}/{quiz}.xml")
    ET.SubElement(res, "dependency", identifierref=f"{quiz}_figures")
    figs = ET.SubElement(resources, "resource", identifier=f"{quiz}_figures", type="webcontent",
                         href=next(iter(files), f"{quiz}/figures"))
    for name in files:
        ET.SubElement(figs, "file", href=name)
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as z:
        z.writestr("imsmanifest.xml", ET.tostring(manifest, encoding="utf-8", xml_declaration=True))
        z.writestr(f"{quiz}/{quiz}.xml", ET.tostring(qroot, encoding="utf-8", xml_declaration=True))
        for name, data in files.items():
            z.writestr(name, data)
    return path


# ----------------------------------------------------------------------------- PDF (Typst)
def _typ(text):
    """A Typst string literal showing ``text`` as it is (no markup)."""
    return '#"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


_PREAMBLE = ('#set page(paper: "a4", margin: 2cm)\n'
             '#set text(font: ("Libertinus Serif", "Noto Serif CJK SC", "Noto Sans CJK SC"), size: 10.5pt, '
             'lang: "en")\n#set par(justify: false)\n')


def _typst_block(lines):
    return "\n".join(_typ(line) + " \\" if line else "" for line in lines)


def write_pdf(students, out, *, title="Problem sheet"):
    """Compile with Typst, into ``out``: ``student_NN.pdf`` (the statements with the
    student's givens and figures, and the answer keys to use), ``student_NN_key.pdf`` (the
    answers by key and the worked solutions) and ``class_list.pdf``. Returns the paths."""
    import typst

    from mech.exercises._text import markdown_to_text

    out = Path(out)
    work = out / "typst"
    work.mkdir(parents=True, exist_ok=True)
    written = []
    for st in students:
        sheet = [_PREAMBLE, f"= {_typ(title)}", f"{_typ(f'{st.label}, seed {st.seed}')}", ""]
        key = [_PREAMBLE, f"= {_typ(title + ': answer key')}", f"{_typ(f'{st.label}, seed {st.seed}')}", ""]
        for it in st.items:
            fig = f"{st.label}_{it.number}.png"
            (work / fig).write_bytes(it.figure)
            sheet += [f"== {_typ(f'Exercise {it.number}: {it.title}')}", "", _typ(it.statement), "",
                      f'#image("{fig}", width: 80%)', "", _typ("Answer with these keys:"), ""]
            sheet += [f"- {_typ(f'{q.key}: {q.what}' + (f' ({q.unit})' if q.unit else ''))}" for q in it.quantities]
            sheet.append("")
            key += [f"== {_typ(f'Exercise {it.number}')}", ""]
            key += [f"- {_typ(f'{q.key} = {_fmt(q.value)} {q.unit}'.rstrip())}" for q in it.quantities]
            key += ["", _typst_block(markdown_to_text(it.solution.as_markdown()).splitlines()), ""]
        for name, lines in ((st.label, sheet), (f"{st.label}_key", key)):
            src = work / f"{name}.typ"
            src.write_text("\n".join(lines), encoding="utf-8")
            typst.compile(str(src), output=str(out / f"{name}.pdf"), root=str(work))
            written.append(out / f"{name}.pdf")
    rows = "".join(f"[{st.index}], [{st.label}], [{st.seed}],\n" for st in students)
    numbers = ", ".join(it.number for it in students[0].items) if students else ""
    src = work / "class_list.typ"
    src.write_text(_PREAMBLE + f"= {_typ(title + ': class list')}\n{_typ('Exercises ' + numbers)}\n\n"
                   "#table(columns: 3, [*student*], [*file*], [*seed*],\n" + rows + ")\n", encoding="utf-8")
    typst.compile(str(src), output=str(out / "class_list.pdf"), root=str(work))
    written.append(out / "class_list.pdf")
    write_class_list(students, out / "class_list.csv")
    return written
