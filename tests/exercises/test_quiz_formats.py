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

On top of QTI 1.2, the profile Canvas's classic quizzes export and import: the item's
``question_type`` metadata one of Canvas's types, a ``numerical_question`` answered in one
``response_str`` (ident ``response1``) with a decimal ``render_fib``, figures referred to
through ``$IMS-CC-FILEBASE$``. A small ASI scorer (:func:`qti_score`) runs each item's
response processing on a response, so that the QTI's grading can be compared with
``check``'s. Neither Moodle nor Canvas runs here: these checks stand in for an import.
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
_CONDITIONS = ("(not |and |or |unanswered |other |varequal |varlt |varlte |vargt |vargte |varsubset |varinside "
               "|varsubstring |durequal |durlt |durlte |durgt |durgte |var_extension )")


def _RESPONSE(*extra):
    """The ASI content model shared by response_lid, response_str and response_num."""
    attrs = {"ident": bool, "rcardinality": {"Single", "Multiple", "Ordered"}, "rtiming": {"Yes", "No"}}
    if "numtype" in extra:
        attrs["numtype"] = {"Integer", "Decimal", "Scientific"}
    return ("(material |material_ref )?((render_choice |render_hotspot |render_slider |render_fib "
            "|render_extension ))(material |material_ref )?", attrs, ("ident",))


_VAR = ("", {"respident": bool, "index": bool, "case": {"Yes", "No"}}, ("respident",))
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
    "selection_extension": ("(points_per_item )?", {}, ()), "points_per_item": _TEXT_ONLY,     # Canvas's
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
    "response_num": _RESPONSE("numtype"),
    "response_str": _RESPONSE(),
    "response_lid": _RESPONSE(),
    "render_choice": ("((material |material_ref |response_label |flow_label ))*",
                      {"shuffle": {"Yes", "No"}, "minnumber": bool, "maxnumber": bool}, ()),
    "response_label": ("((qticomment |material |material_ref |flow_mat ))*",
                       {"ident": bool, "rshuffle": {"Yes", "No"}, "rarea": {"Ellipse", "Rectangle", "Bounded"},
                        "rrange": {"Exact", "Range"}, "labelrefid": bool, "match_group": bool, "match_max": bool},
                       ("ident",)),
    "render_fib": ("((material |material_ref |response_label |flow_label ))*",
                   {"fibtype": {"String", "Integer", "Decimal", "Scientific"}, "prompt": bool, "rows": bool,
                    "columns": bool, "maxchars": bool, "minnumber": bool, "maxnumber": bool}, ()),
    "resprocessing": ("(qticomment )?outcomes ((respcondition |itemproc_extension ))+", {"scoremodel": bool}, ()),
    "outcomes": ("(qticomment )?((decvar |interpretvar ))+", {}, ()),
    "decvar": ("", {"varname": bool, "vartype": _ENUM_VARTYPE, "defaultval": bool, "minvalue": _NUM.match,
                    "maxvalue": _NUM.match, "members": bool, "cutvalue": bool}, ()),
    "respcondition": ("(qticomment )?conditionvar (setvar )*(displayfeedback )*(respcond_extension )?",
                      {"title": bool, "continue": {"Yes", "No"}}, ()),
    "conditionvar": (f"({_CONDITIONS})+", {}, ()),
    "or": (f"({_CONDITIONS})+", {}, ()), "and": (f"({_CONDITIONS})+", {}, ()), "not": (_CONDITIONS, {}, ()),
    "other": _TEXT_ONLY, "unanswered": ("", {"respident": bool}, ("respident",)),
    "varequal": _VAR, "vargte": _VAR, "varlte": _VAR, "vargt": _VAR, "varlt": _VAR,
    "displayfeedback": ("", {"feedbacktype": {"Response", "Solution", "Hint"}, "linkrefid": bool}, ("linkrefid",)),
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


_ASI = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"


def _strip_ns(el, ns=_CP):
    for e in el.iter():
        if e.tag.startswith(ns):
            e.tag = e.tag[len(ns):]
    return el


def read_qti(data):
    """The QTI document ``data`` (bytes) parsed, with the ASI namespace (which the XML
    binding declares and the DTD form leaves out) removed from the tags."""
    return _strip_ns(ET.fromstring(data), _ASI)


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
        raw = ET.fromstring(z.read(href))
        if raw.tag not in ("questestinterop", _ASI + "questestinterop"):
            errors.append(f"root {raw.tag!r} is not questestinterop (in the ASI namespace or none)")
        root = _strip_ns(raw, _ASI)
        errors += _conform(root, QTI)
        idents = [e.get("ident") for e in root.iter() if e.tag in ("assessment", "section", "item")]
        if len(idents) != len(set(idents)):
            errors.append("assessment, section and item idents repeat")
        for item in root.iter("item"):
            errors += _item_errors(item, names)
    return errors


# ----------------------------------------------------------------------------- Canvas's profile
#: The question types of Canvas's classic quizzes, as its QTI export and import name them
#: in the item's ``question_type`` metadata.
CANVAS_TYPES = {"multiple_choice_question", "true_false_question", "short_answer_question",
                "fill_in_multiple_blanks_question", "multiple_answers_question", "multiple_dropdowns_question",
                "matching_question", "numerical_question", "calculated_question", "essay_question",
                "file_upload_question", "text_only_question"}
CANVAS_FILEBASE = "$IMS-CC-FILEBASE$/"


def _item_errors(item, names):
    """Errors of one item against the ASI rules that cross elements and Canvas's profile
    of a ``numerical_question``: one ``response_str`` named response1 with a decimal blank,
    scored by conditions on that response, its figures under ``$IMS-CC-FILEBASE$``."""
    who = item.get("ident")
    errors = []
    meta = {f.findtext("fieldlabel"): f.findtext("fieldentry") for f in item.iter("qtimetadatafield")}
    kind = meta.get("question_type")
    if kind not in CANVAS_TYPES:
        errors.append(f"{who}: question_type {kind!r} is not a Canvas question type")
    try:
        if not float(meta.get("points_possible", "")) > 0:
            errors.append(f"{who}: points_possible not positive")
    except ValueError:
        errors.append(f"{who}: points_possible {meta.get('points_possible')!r} not a number")
    responses = [r for r in item.iter() if r.tag in ("response_lid", "response_str", "response_num")]
    rids = [r.get("ident") for r in responses]
    if len(rids) != len(set(rids)) or not rids:
        errors.append(f"{who}: responses missing or repeated")
    if kind == "numerical_question":
        if [(r.tag, r.get("ident")) for r in responses] != [("response_str", "response1")]:
            errors.append(f"{who}: a numerical_question has one response_str response1, got "
                          f"{[(r.tag, r.get('ident')) for r in responses]}")
        elif responses[0].find("render_fib") is None or responses[0].find("render_fib").get("fibtype") != "Decimal":
            errors.append(f"{who}: the blank of a numerical_question is not a decimal render_fib")
    feedback = {f.get("ident") for f in item.iter("itemfeedback")}
    for c in item.iter("respcondition"):
        for v in c.find("conditionvar").iter():
            if v.tag.startswith("var"):
                if v.get("respident") not in rids:
                    errors.append(f"{who}: condition on an unknown response")
                if kind == "numerical_question" and not _NUM.match((v.text or "").strip()):
                    errors.append(f"{who}: bound {v.text!r} not a number")
        errors += [f"{who}: feedback {d.get('linkrefid')} not in the item" for d in c.iter("displayfeedback")
                   if d.get("linkrefid") not in feedback]
    for src in re.findall(r'src="([^"]+)"', "".join(m.text or "" for m in item.iter("mattext"))):
        if not src.startswith(CANVAS_FILEBASE):
            errors.append(f"{who}: image {src} not under {CANVAS_FILEBASE}")
        elif src[len(CANVAS_FILEBASE):] not in names:
            errors.append(f"{who}: image {src} not in the zip")
    return errors


def _holds(cond, response):
    """Whether the ASI condition ``cond`` holds for a decimal ``response`` (a string)."""
    tag = cond.tag
    if tag in ("conditionvar", "and"):
        return all(_holds(c, response) for c in cond)
    if tag == "or":
        return any(_holds(c, response) for c in cond)
    if tag == "not":
        return not _holds(cond[0], response)
    if tag == "other":
        return True
    x, bound = float(response), float(cond.text)
    return {"varequal": x == bound, "vargte": x >= bound, "varlte": x <= bound, "vargt": x > bound,
            "varlt": x < bound}[tag]


def qti_score(item, response):
    """The SCORE an ASI processor gives ``response`` on ``item``, as a fraction of the
    ``decvar``'s maximum: the conditions in order, ``continue="No"`` (the default) stops."""
    proc = item.find("resprocessing")
    decvar = proc.find("outcomes/decvar")
    score = float(decvar.get("defaultval", "0"))
    for c in proc.findall("respcondition"):
        if _holds(c.find("conditionvar"), response):
            for sv in c.findall("setvar"):
                v = float(sv.text)
                score = {"Set": v, "Add": score + v, "Subtract": score - v, "Multiply": score * v,
                         "Divide": score / v}[sv.get("action", "Set")]
            if c.get("continue", "No") == "No":
                break
    return score / float(decvar.get("maxvalue"))


# ----------------------------------------------------------------------------- the tests
NUMBERS = ["2-3", "2-20", "2-24", "E2-1", "E2-9"]       # one answer (2-20) and several


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


def _qti_items(path):
    with zipfile.ZipFile(path) as z:
        root = read_qti(z.read("mech_quiz/mech_quiz.xml"))
    return [s for s in root.iter("section") if s.find("selection_ordering") is not None]


def test_qti_multiple_answers_one_numerical_question_each(quiz_files):
    """Canvas has no question with several numerical blanks: an exercise with k answers is
    k groups (one per answer) of numerical_question items, one item per student variant,
    and the ASI scoring of each item agrees with ``check`` on four responses: the answer,
    a number just inside and just outside ``check``'s tolerance, and a far one."""
    from mech.exercises import get
    from mech.exercises._sheet import answer_quantities, check_answers, solved_variant, student_seeds

    sections = _qti_items(quiz_files / "quiz.zip")
    seeds = student_seeds(11, 2)
    multi = 0
    for number in NUMBERS:
        ex = get(number)
        keyed = {s: answer_quantities(solved_variant(ex, s)[1]) for s in seeds}
        keys = [q.key for q in keyed[seeds[0]]]
        groups = [sec for sec in sections if sec.get("ident").startswith(f"section_{number}_")]
        assert [sec.get("ident") for sec in groups] == [f"section_{number}_{k}" for k in keys]
        multi += len(keys) > 1
        for sec, key in zip(groups, keys):
            assert sec.findtext("selection_ordering/selection/selection_number") == "1"
            items = sec.findall("item")
            assert [i.get("ident") for i in items] == [f"item_{number}_{key}_{s}" for s in seeds]
            for item, s in zip(items, seeds):
                q = next(q for q in keyed[s] if q.key == key)
                tol = q.tolerance()
                for response, right in ((q.value, True), (q.value + 0.98 * tol, True),
                                        (q.value - 1.02 * tol, False), (q.value + 10 * tol + 1, False)):
                    text = f"{response:.9g}"
                    assert qti_score(item, text) == (1.0 if right else 0.0), (item.get("ident"), text)
                    verdict, = check_answers(ex, s, {key: text + (f" {q.unit}" if q.unit else "")})
                    assert verdict.right == right, (item.get("ident"), text)
    assert multi >= 3                                  # 2-3, 2-24 and E2-9 ask for several


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
    ("manifest", "missing file"), ("response_num", "one response_str response1"),
    ("type", "not a Canvas question type"), ("filebase", "not under $IMS-CC-FILEBASE$"),
    ("feedback", "feedback general_fb not in the item"), ("bound", "not a number"),
])
def test_qti_validator_finds_planted_faults(quiz_files, tmp_path, fault, message):
    src, dst = quiz_files / "quiz.zip", tmp_path / "bad.zip"
    with zipfile.ZipFile(src) as z:
        parts = {n: z.read(n) for n in z.namelist()}
    quiz = "mech_quiz/mech_quiz.xml"
    root = read_qti(parts[quiz])
    item = root.find(".//item")
    if fault == "item_order":                    # resprocessing before presentation
        pres = item.find("presentation")
        item.remove(pres)
        item.append(pres)
    elif fault == "setvar":
        item.find(".//setvar").set("action", "Plus")
    elif fault == "figure":
        del parts[next(n for n in parts if n.endswith(".png"))]
    elif fault == "response_num":                # the blank as QTI allows, not as Canvas reads
        item.find(".//response_str").tag = "response_num"
    elif fault == "type":
        next(f for f in item.iter("fieldentry") if f.text == "numerical_question").text = "numeric"
    elif fault == "filebase":
        m = item.find("presentation/material/mattext")
        m.text = m.text.replace("$IMS-CC-FILEBASE$/", "")
    elif fault == "feedback":
        item.remove(item.find("itemfeedback"))
    elif fault == "bound":
        item.find(".//vargte").text = "about 3"
    else:
        del parts[quiz]
    if fault != "manifest":
        parts[quiz] = ET.tostring(root, encoding="utf-8", xml_declaration=True)
    with zipfile.ZipFile(dst, "w") as z:
        for n, data in parts.items():
            z.writestr(n, data)
    errors = validate_qti(dst)
    assert any(message in e for e in errors), errors
