"""A class's variants exported to the formats schools use: Moodle XML, QTI 1.2 (Canvas),
PDF through Typst, and Markdown and HTML, one file per student.

:func:`build_class` draws every student's variant of every chosen exercise once (the seeds
of :func:`~mech.exercises._sheet.student_seeds`); the writers turn that into files:

- :func:`write_moodle`: one question per exercise and student, in a category per exercise
  (so that a quiz's random question draws one variant per student), numerical answers with
  the tolerance ``check`` uses and units, the variant's figure embedded as a base64
  ``<file>``, and the worked solution as general feedback;
- :func:`write_qti`: a zip with ``imsmanifest.xml`` and a QTI 1.2 assessment in the profile
  Canvas imports: a ``numerical_question`` per answer and student variant, in sections (one
  per exercise and answer, drawing one item), the figures as files;
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
#: Canvas's folder token: its importer points a reference that starts with it at the
#: package's root, where the figures are stored.
CANVAS_FILEBASE = "$IMS-CC-FILEBASE$"
#: The namespace of the QTI 1.2 ASI XML binding, which Canvas's own export declares.
QTI_ASI_NAMESPACE = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"


def _qti_meta(item, fields):
    meta = _sub(_sub(item, "itemmetadata"), "qtimetadata")
    for label, entry in fields:
        field = _sub(meta, "qtimetadatafield")
        _sub(field, "fieldlabel").text = label
        _sub(field, "fieldentry").text = entry


def _sub(parent, tag, **attrs):
    import xml.etree.ElementTree as ET

    return ET.SubElement(parent, tag, **attrs)


def _qti_numerical_item(section, ident, title, html_text, value, tol, feedback):
    """One item in the profile Canvas writes and reads for a ``numerical_question``: a
    ``response_str`` with a decimal blank, and one condition ``value`` exactly or within
    ``[value - tol, value + tol]`` that sets the score to 100; the worked solution as the
    general feedback shown whatever the answer."""
    item = _sub(section, "item", ident=ident, title=title)
    _qti_meta(item, (("question_type", "numerical_question"), ("points_possible", "1.0")))
    pres = _sub(item, "presentation")
    _sub(_sub(pres, "material"), "mattext", texttype="text/html").text = html_text
    resp = _sub(pres, "response_str", ident="response1", rcardinality="Single")
    _sub(_sub(resp, "render_fib", fibtype="Decimal"), "response_label", ident="answer1")
    proc = _sub(item, "resprocessing")
    _sub(_sub(proc, "outcomes"), "decvar", maxvalue="100", minvalue="0", varname="SCORE", vartype="Decimal")
    general = _sub(proc, "respcondition", **{"continue": "Yes"})
    _sub(_sub(general, "conditionvar"), "other")
    _sub(general, "displayfeedback", feedbacktype="Response", linkrefid="general_fb")
    cond = _sub(proc, "respcondition", **{"continue": "No"})
    either = _sub(_sub(cond, "conditionvar"), "or")
    # ten digits: Canvas takes the margin as upper bound minus the exact value
    _sub(either, "varequal", respident="response1").text = f"{value:.10g}"
    both = _sub(either, "and")
    _sub(both, "vargte", respident="response1").text = f"{value - tol:.10g}"
    _sub(both, "varlte", respident="response1").text = f"{value + tol:.10g}"
    _sub(cond, "setvar", action="Set", varname="SCORE").text = "100"
    fb = _sub(item, "itemfeedback", ident="general_fb")
    _sub(_sub(_sub(fb, "flow_mat"), "material"), "mattext", texttype="text/html").text = feedback
    return item


def write_qti(students, path, *, rtol=0.01, atol=0.01, title="mech exercises"):
    """Write a QTI 1.2 zip for Canvas to ``path``: ``imsmanifest.xml``, the assessment
    ``mech_quiz/mech_quiz.xml`` and the figures in ``images/``.

    Canvas's classic quizzes have one numerical question type, ``numerical_question``,
    with a single number and a margin; a question with several numerical blanks does not
    exist there (its fill-in-multiple-blanks and dropdown types match text or choices,
    not a number within a tolerance). So each answer of an exercise is a question of its
    own: the section (a question group that draws one item, inside the assessment's
    ``root_section`` as Canvas writes it) ``Exercise N: key`` holds one item per student
    variant, each with the full statement, its figure and the one
    quantity asked, scored within the tolerance ``check`` uses (``rtol * |value| + atol``).
    The groups draw independently, so the answers of one exercise may come from different
    variants; every item stands alone. The figures are referred to through Canvas's
    ``$IMS-CC-FILEBASE$`` token. Returns ``path``."""
    import xml.etree.ElementTree as ET
    import zipfile

    quiz = "mech_quiz"
    qroot = ET.Element("questestinterop", xmlns=QTI_ASI_NAMESPACE)
    assessment = _sub(qroot, "assessment", ident=quiz, title=title)
    root_section = _sub(assessment, "section", ident="root_section")    # as Canvas nests its groups
    files = {}
    numbers = [it.number for it in students[0].items] if students else []
    for j, number in enumerate(numbers):
        keys = [q.key for q in students[0].items[j].quantities]
        for p, key in enumerate(keys):
            part = f"Exercise {number}" + (f": {key}" if len(keys) > 1 else "")
            section = _sub(root_section, "section", ident=f"section_{number}_{key}", title=part)
            sel = _sub(_sub(section, "selection_ordering"), "selection")
            _sub(sel, "selection_number").text = "1"              # one variant per student
            _sub(_sub(sel, "selection_extension"), "points_per_item").text = "1.0"
            for st in students:
                it = st.items[j]
                qq = it.quantities[p]
                fig = f"images/exercise_{number}_{st.seed}.png"
                files[fig] = it.figure
                text = (f"<p>{html.escape(it.statement)}</p><p><img src=\"{CANVAS_FILEBASE}/{fig}\" "
                        f"alt=\"Figure of exercise {number}\"></p><p>Answer {p + 1} of {len(keys)}: "
                        f"{html.escape(qq.what)} (<code>{qq.key}</code>)"
                        + (f", in {html.escape(qq.unit)}" if qq.unit else "") + ".</p>")
                _qti_numerical_item(section, f"item_{number}_{key}_{st.seed}", f"{part}, variant {st.seed}",
                                    text, qq.value, qq.tolerance(rtol, atol), _solution_html(it))
    ns = "http://www.imsglobal.org/xsd/imscp_v1p1"
    manifest = ET.Element("manifest", identifier=f"{quiz}_manifest", xmlns=ns)
    md = _sub(manifest, "metadata")
    _sub(md, "schema").text = "IMS Content"
    _sub(md, "schemaversion").text = "1.1.3"
    _sub(manifest, "organizations")
    resources = _sub(manifest, "resources")
    res = _sub(resources, "resource", identifier=quiz, type="imsqti_xmlv1p2")
    _sub(res, "file", href=f"{quiz}/{quiz}.xml")
    for k, name in enumerate(files):
        _sub(res, "dependency", identifierref=f"{quiz}_figure_{k}")
    for k, name in enumerate(files):             # one webcontent resource per figure
        _sub(_sub(resources, "resource", identifier=f"{quiz}_figure_{k}", type="webcontent", href=name),
             "file", href=name)
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
