"""The Moodle XML and the QTI zip checked against the structure of their formats.

Each element the writers emit is checked against a content model written here from the
formats' own definitions, not from the writers: for Moodle's XML question format, the
elements of a category, a numerical and a Cloze (multianswer) question, the tolerance of
each answer, units, the figure as a base64 ``<file>`` that the text refers to by
``@@PLUGINFILE@@``, general feedback, and Cloze's ``{1:NUMERICAL:=value:tolerance}``
with numbers as Moodle's Cloze parser reads them; for QTI 1.2 (ASI), the content models
and enumerated attributes of the ASI DTD for every element used, and for the IMS content
package, those of ``imsmanifest.xml`` (IMS CP 1.1). A model is a regular expression over
the sequence of an element's child tags; an element not in the models is an error.
"""

import base64
import re
import xml.etree.ElementTree as ET
import zipfile

import pytest

_N = r"-?(?:[0-9]+[.,]?[0-9]*|[.,][0-9]+)(?:[eE][-+]?[0-9]+)?"     # a number as Moodle's Cloze reads it
_NUM = re.compile(_N + r"$")
_CLOZE = re.compile(r"\{(\d+):(NUMERICAL|NM):=(" + _N + r"):(" + _N + r")\}")
_FORMATS = {"html", "moodle_auto_format", "plain_text", "markdown"}

# ----------------------------------------------------------------------------- Moodle
# element -> (child model, {attribute: allowed values or a predicate}, required attributes)
_TEXT_ONLY = ("", {}, ())
MOODLE = {
    "quiz": ("(question )+", {}, ()),
    "question@category": ("category (info )?", {"type": {"category"}}, ("type",)),
    "question@numerical": ("name questiontext generalfeedback defaultgrade penalty hidden (idnumber )?answer+ "
                           "(units )?(unitgradingtype unitpenalty showunits unitsleft )?(instructions )?",
                           {"type": {"numerical"}}, ("type",)),
    "question@cloze": ("name questiontext generalfeedback (defaultgrade )?penalty hidden (idnumber )?",
                       {"type": {"cloze"}}, ("type",)),
    "category": ("text ", {}, ()),
    "name": ("text ", {}, ()),
    "questiontext": ("text (file )*", {"format": _FORMATS}, ("format",)),
    "generalfeedback": ("text (file )*", {"format": _FORMATS}, ()),
    "answer": ("text (tolerance )?(feedback )?", {"fraction": lambda v: _NUM.match(v) and 0 <= float(v) <= 100,
                                                 "format": _FORMATS}, ("fraction",)),
    "feedback": ("text (file )*", {"format": _FORMATS}, ()),
    "units": ("(unit )+", {}, ()),
    "unit": ("multiplier unit_name ", {}, ()),
    "file": ("", {"name": lambda v: bool(v), "path": {"/"}, "encoding": {"base64"}}, ("name", "path", "encoding")),
    "text": _TEXT_ONLY, "defaultgrade": _TEXT_ONLY, "penalty": _TEXT_ONLY, "hidden": _TEXT_ONLY,
    "tolerance": _TEXT_ONLY, "multiplier": _TEXT_ONLY, "unit_name": _TEXT_ONLY, "unitgradingtype": _TEXT_ONLY,
    "unitpenalty": _TEXT_ONLY, "showunits": _TEXT_ONLY, "unitsleft": _TEXT_ONLY,
}
_LEAF_VALUES = {
    "defaultgrade": lambda v: _NUM.match(v) and float(v) > 0, "penalty": lambda v: 0 <= float(v) <= 1,
    "hidden": {"0", "1"}, "tolerance": lambda v: _NUM.match(v) and float(v) > 0,
    "multiplier": lambda v: _NUM.match(v) and float(v) > 0, "unitgradingtype": {"0", "1", "2"},
    "unitpenalty": lambda v: 0 <= float(v) <= 1, "showunits": {"0", "1", "2", "3"}, "unitsleft": {"0", "1"},
    "unit_name": lambda v: bool(v.strip()),
}


def _allowed(rule, value):
    return value in rule if isinstance(rule, set) else bool(rule(value))


def _conform(el, models, key=None, where=""):
    """Errors of ``el`` and its descendants against ``models`` (a list of strings)."""
    key = key or el.tag
    where = f"{where}/{key}"
    if key not in models:
        return [f"{where}: element not in the format"]
    model, attrs, required = models[key]
    errors = []
    seq = "".join(f"{c.tag} " for c in el)
    if not re.fullmatch(model, seq):
        errors.append(f"{where}: children {seq!r} do not fit {model!r}")
    for a in required:
        if a not in el.attrib:
            errors.append(f"{where}: required attribute {a} missing")
    for a, v in el.attrib.items():
        if a not in attrs:
            errors.append(f"{where}: attribute {a} not in the format")
        elif not _allowed(attrs[a], v):
            errors.append(f"{where}: {a}={v!r} not allowed")
    if model == "" and len(el):
        errors.append(f"{where}: a text element with children")
    for c in el:
        ckey = f"question@{c.get('type')}" if c.tag == "question" else c.tag
        errors += _conform(c, models, ckey, where)
    return errors


def validate_moodle(path):
    """Every error of the Moodle XML file ``path`` (an empty list when it conforms)."""
    root = ET.parse(path).getroot()
    errors = _conform(root, MOODLE)
    for el in root.iter():
        if el.tag in _LEAF_VALUES and not _allowed(_LEAF_VALUES[el.tag], (el.text or "").strip()):
            errors.append(f"{el.tag}: value {el.text!r} not allowed")
    category = None
    for q in root.findall("question"):
        kind = q.get("type")
        if kind == "category":
            category = q.findtext("category/text")
            if not category or not category.startswith("$course$/"):
                errors.append(f"category {category!r} not under $course$")
            continue
        name = q.findtext("name/text")
        if category is None:
            errors.append(f"{name}: a question before any category")
        text = q.findtext("questiontext/text") or ""
        files = {f.get("name"): f.text for f in q.findall("questiontext/file")}
        for ref in re.findall(r'src="@@PLUGINFILE@@/([^"]+)"', text):
            data = files.get(ref)
            if data is None:
                errors.append(f"{name}: image {ref} has no <file>")
            elif base64.b64decode(data, validate=True)[:8] != b"\x89PNG\r\n\x1a\n":
                errors.append(f"{name}: <file> {ref} is not a base64 PNG")
        if not files or not re.search(r'src="@@PLUGINFILE@@/', text):
            errors.append(f"{name}: no embedded image")
        if not (q.findtext("generalfeedback/text") or "").strip():
            errors.append(f"{name}: no general feedback")
        if kind == "numerical":
            for a in q.findall("answer"):
                if not _NUM.match((a.findtext("text") or "").strip()) or a.find("tolerance") is None:
                    errors.append(f"{name}: answer without a number and a tolerance")
            if not any(a.get("fraction") == "100" for a in q.findall("answer")):
                errors.append(f"{name}: no answer worth 100 %")
        else:
            macros = re.findall(r"\{\d+:[^}]*\}", text)
            good = _CLOZE.findall(text)
            if not good or len(good) != len(macros):
                errors.append(f"{name}: Cloze answers {macros[:3]} not all NUMERICAL:=value:tolerance")
            if any(float(t.replace(",", ".")) <= 0 for *_, t in good):
                errors.append(f"{name}: a Cloze tolerance not positive")
    return errors


# ----------------------------------------------------------------------------- QTI 1.2 (ASI DTD)
_ENUM_VARTYPE = {"Integer", "String", "Decimal", "Scientific", "Boolean", "Enumerated", "Set"}
QTI = {
    "questestinterop": ("(qticomment )?(objectbank |assessment |((section |item )+))", {}, ()),
    "assessment": ("(qticomment )?(duration )?(qtimetadata )*(objectives )*(assessmentcontrol )*(rubric )*"
                   "(presentation_material )?(outcomes_processing )*(assessproc_extension )?(assessfeedback )*"
                   "(selection_ordering )?(reference )?((sectionref |section )+)",
                   {"ident": bool, "title": bool, "xml:lang": bool}, ("ident",)),
    "section": ("(qticomment )?(duration )?(qtimetadata )*(objectives )*(sectioncontrol )*"
                "(sectionprecondition )*(sectionpostcondition )*(rubric )*(presentation_material )?"
                "(outcomes_processing )*(sectionproc_extension )?(sectionfeedback )*(selection_ordering )?"
                "(reference )?((itemref |item |sectionref |section )*)", {"ident": bool, "title": bool}, ("ident",)),
    "selection_ordering": ("(qticomment )?(sequence_parameter )*(selection )*(order )?", {"sequence_type": bool}, ()),
    "selection": ("(sourcebank_ref )?(selection_number )?(selection_metadata )?"
                  "((and_selection |or_selection |not_selection |selection_extension ))?", {}, ()),
    "selection_number": _TEXT_ONLY,
    "item": ("(qticomment )?(duration )?(itemmetadata )?(objectives )*(itemcontrol )*(itemprecondition )*"
             "(itempostcondition )*((itemrubric |rubric ))*(presentation )?(resprocessing )*"
             "(itemproc_extension )?(itemfeedback )*(reference )?",
             {"ident": bool, "title": bool, "label": bool, "maxattempts": bool}, ("ident",)),
    "itemmetadata": ("(qtimetadata )*", {}, ()),
    "qtimetadata": ("(vocabulary )?(qtimetadatafield )+", {}, ()),
    "qtimetadatafield": ("fieldlabel fieldentry ", {}, ()),
    "fieldlabel": _TEXT_ONLY, "fieldentry": _TEXT_ONLY,
    "presentation": ("(qticomment )?((flow |(material |response_lid |response_xy |response_str |response_num "
                     "|response_grp |response_extension )+))", {"label": bool}, ()),
    "material": ("(qticomment )?((mattext |matemtext |matimage |mataudio |matvideo |matapplet |matapplication "
                 "|matref |matbreak |mat_extension )+)(altmaterial )*", {"label": bool}, ()),
    "mattext": ("", {"texttype": bool, "label": bool, "charset": bool, "uri": bool}, ()),
    "response_num": ("(material |material_ref )?((render_choice |render_hotspot |render_slider |render_fib "
                     "|render_extension ))(material |material_ref )?",
                     {"ident": bool, "rcardinality": {"Single", "Multiple", "Ordered"},
                      "numtype": {"Integer", "Decimal", "Scientific"}, "rtiming": {"Yes", "No"}}, ("ident",)),
    "render_fib": ("((material |material_ref |response_label |flow_label ))*",
                   {"fibtype": {"String", "Integer", "Decimal", "Scientific"}, "prompt": bool, "rows": bool,
                    "columns": bool, "maxchars": bool, "minnumber": bool, "maxnumber": bool}, ()),
    "resprocessing": ("(qticomment )?outcomes ((respcondition |itemproc_extension ))+", {"scoremodel": bool}, ()),
    "outcomes": ("(qticomment )?((decvar |interpretvar ))+", {}, ()),
    "decvar": ("", {"varname": bool, "vartype": _ENUM_VARTYPE, "defaultval": bool, "minvalue": _NUM.match,
                    "maxvalue": _NUM.match, "members": bool, "cutvalue": bool}, ()),
    "respcondition": ("(qticomment )?conditionvar (setvar )*(displayfeedback )*(respcond_extension )?",
                      {"title": bool, "continue": {"Yes", "No"}}, ()),
    "conditionvar": ("((not |and |or |unanswered |other |varequal |varlt |varlte |vargt |vargte |varsubset "
                     "|varinside |varsubstring |durequal |durlt |durlte |durgt |durgte |var_extension ))+", {}, ()),
    "vargte": ("", {"respident": bool, "index": bool}, ("respident",)),
    "varlte": ("", {"respident": bool, "index": bool}, ("respident",)),
    "setvar": ("", {"varname": bool, "action": {"Set", "Add", "Subtract", "Multiply", "Divide"}}, ()),
    "itemfeedback": ("((flow_mat |material |solution |hint ))+", {"ident": bool, "view": bool, "title": bool},
                     ("ident",)),
    "flow_mat": ("(qticomment )?((flow_mat |material |material_ref ))+", {"class": bool}, ()),
}
MANIFEST = {
    "manifest": ("(metadata )?organizations resources (manifest )*", {"identifier": bool, "version": bool},
                 ("identifier",)),
    "metadata": ("(schema )?(schemaversion )?.*", {}, ()),
    "schema": _TEXT_ONLY, "schemaversion": _TEXT_ONLY,
    "organizations": ("(organization )*", {"default": bool}, ()),
    "resources": ("(resource )*", {}, ()),
    "resource": ("(metadata )?(file )*(dependency )*", {"identifier": bool, "type": bool, "href": bool},
                 ("identifier", "type")),
    "file": ("(metadata )?", {"href": bool}, ("href",)),
    "dependency": ("", {"identifierref": bool}, ("identifierref",)),
}
_CP = "{http://www.imsglobal.org/xsd/imscp_v1p1}"


def _strip_ns(el):
    for e in el.iter():
        if e.tag.startswith(_CP):
            e.tag = e.tag[len(_CP):]
    return el


def validate_qti(path):
    """Every error of the QTI 1.2 zip ``path`` (an empty list when it conforms)."""
    errors = []
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        raw = ET.fromstring(z.read("imsmanifest.xml"))
        if raw.tag != _CP + "manifest":
            errors.append(f"manifest in namespace {raw.tag!r}, not IMS CP 1.1")
        man = _strip_ns(raw)
        errors += _conform(man, MANIFEST)
        ids = [r.get("identifier") for r in man.iter("resource")]
        if len(ids) != len(set(ids)):
            errors.append("resource identifiers repeat")
        for r in man.iter("resource"):
            errors += [f"manifest names a missing file {f.get('href')}" for f in r.iter("file")
                       if f.get("href") not in names]
            errors += [f"dependency on an unknown resource {d.get('identifierref')}" for d in r.iter("dependency")
                       if d.get("identifierref") not in ids]
        qti = [r for r in man.iter("resource") if r.get("type") == "imsqti_xmlv1p2"]
        if len(qti) != 1:
            return errors + [f"expected one imsqti_xmlv1p2 resource, got {len(qti)}"]
        href = qti[0].find("file").get("href")
        if href not in names:
            return errors
        root = ET.fromstring(z.read(href))
        errors += _conform(root, QTI)
        idents = [e.get("ident") for e in root.iter() if e.tag in ("assessment", "section", "item")]
        if len(idents) != len(set(idents)):
            errors.append("assessment, section and item idents repeat")
        base = href.rsplit("/", 1)[0]
        for item in root.iter("item"):
            rids = [r.get("ident") for r in item.iter("response_num")]
            if len(rids) != len(set(rids)) or not rids:
                errors.append(f"{item.get('ident')}: responses missing or repeated")
            for c in item.iter("respcondition"):
                for v in c.find("conditionvar"):
                    if v.get("respident") not in rids:
                        errors.append(f"{item.get('ident')}: condition on an unknown response")
                    if not _NUM.match((v.text or "").strip()):
                        errors.append(f"{item.get('ident')}: bound {v.text!r} not a number")
            for src in re.findall(r'src="([^"]+)"', "".join(m.text or "" for m in item.iter("mattext"))):
                if f"{base}/{src}" not in names:
                    errors.append(f"{item.get('ident')}: image {src} not in the zip")
    return errors


# ----------------------------------------------------------------------------- the tests
NUMBERS = ["2-3", "2-20", "2-24", "E2-1", "E2-9"]       # numerical (2-20) and Cloze questions


@pytest.fixture(scope="module")
def quiz_files(tmp_path_factory):
    from mech.exercises._export import build_class, write_moodle, write_qti

    out = tmp_path_factory.mktemp("quiz")
    students = build_class(NUMBERS, students=2, seed=11)
    write_moodle(students, out / "quiz.xml")
    write_qti(students, out / "quiz.zip")
    return out


def test_moodle_xml_conforms(quiz_files):
    assert validate_moodle(quiz_files / "quiz.xml") == []
    root = ET.parse(quiz_files / "quiz.xml").getroot()
    kinds = [q.get("type") for q in root.findall("question")]
    assert kinds.count("category") == len(NUMBERS) and "numerical" in kinds and "cloze" in kinds


def test_qti_zip_conforms(quiz_files):
    assert validate_qti(quiz_files / "quiz.zip") == []


def _edit_xml(src, dst, edit):
    tree = ET.parse(src)
    edit(tree.getroot())
    tree.write(dst, encoding="utf-8", xml_declaration=True)


@pytest.mark.parametrize("edit, message", [
    (lambda r: r.find("question[@type='numerical']/answer").remove(
        r.find("question[@type='numerical']/answer/tolerance")), "answer without a number and a tolerance"),
    (lambda r: r.find("question[@type='numerical']/questiontext").remove(
        r.find("question[@type='numerical']/questiontext/file")), "has no <file>"),
    (lambda r: r.find("question[@type='numerical']/generalfeedback/text").__setattr__("text", " "),
     "no general feedback"),
    (lambda r: r.find("question[@type='cloze']/questiontext/text").__setattr__(
        "text", r.find("question[@type='cloze']/questiontext/text").text.replace(":=", ":=nan", 1)),
     "not all NUMERICAL"),
    (lambda r: r.remove(r.find("question[@type='category']")), "before any category"),
    (lambda r: r.find("question[@type='numerical']").insert(0, ET.Element("bogus")), "element not in the format"),
    (lambda r: r.find("question[@type='numerical']/questiontext").set("format", "docx"), "not allowed"),
])
def test_moodle_validator_finds_planted_faults(quiz_files, tmp_path, edit, message):
    """The validator can fail: each planted fault is named."""
    _edit_xml(quiz_files / "quiz.xml", tmp_path / "bad.xml", edit)
    errors = validate_moodle(tmp_path / "bad.xml")
    assert any(message in e for e in errors), errors


@pytest.mark.parametrize("fault, message", [
    ("item_order", "do not fit"), ("setvar", "action='Plus' not allowed"), ("figure", "not in the zip"),
    ("manifest", "missing file"),
])
def test_qti_validator_finds_planted_faults(quiz_files, tmp_path, fault, message):
    src, dst = quiz_files / "quiz.zip", tmp_path / "bad.zip"
    with zipfile.ZipFile(src) as z:
        parts = {n: z.read(n) for n in z.namelist()}
    quiz = "mech_quiz/mech_quiz.xml"
    root = ET.fromstring(parts[quiz])
    item = root.find(".//item")
    if fault == "item_order":                    # resprocessing before presentation
        pres = item.find("presentation")
        item.remove(pres)
        item.append(pres)
    elif fault == "setvar":
        item.find(".//setvar").set("action", "Plus")
    elif fault == "figure":
        del parts[next(n for n in parts if n.endswith(".png"))]
    else:
        del parts[quiz]
    if fault != "manifest":
        parts[quiz] = ET.tostring(root, encoding="utf-8", xml_declaration=True)
    with zipfile.ZipFile(dst, "w") as z:
        for n, data in parts.items():
            z.writestr(n, data)
    errors = validate_qti(dst)
    assert any(message in e for e in errors), errors
