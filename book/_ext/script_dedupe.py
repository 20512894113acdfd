"""Drop repeated inline scripts from a page's ``<head>``.

sphinx-thebe adds its configuration (``const THEBE_JS_URL = ...``) as an inline script;
when that reaches a page twice, the second copy throws "Identifier 'THEBE_JS_URL' has
already been declared" in the reader's console (found by ``tests/browser``). A page needs
each script once, so identical entries after the first are removed.
"""


def dedupe_scripts(app, pagename, templatename, context, doctree):
    scripts = context.get("script_files")
    if not scripts:
        return
    seen, kept = set(), []
    for script in scripts:
        # The same script reaches the builder twice, once with filename None and once
        # with filename "" (and possibly another priority): compare what the page gets.
        attributes = getattr(script, "attributes", {}) or {}
        key = (str(getattr(script, "filename", script) or ""), tuple(sorted(attributes.items())))
        if key not in seen:
            seen.add(key)
            kept.append(script)
    context["script_files"] = kept


def setup(app):
    # After every extension has added its scripts to the page.
    app.connect("html-page-context", dedupe_scripts, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
