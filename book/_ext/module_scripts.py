"""Keep the generated JavaScript kernels off every page's script tags.

Jupyter Book 1 adds every ``*.js`` file under ``book/_static`` to every page as a classic
script. The kernels in ``_static/kernels`` and their layer in ``_static/mech`` are ES
modules that a page imports only when it needs them: as classic scripts they throw on
``export`` and would weigh on every page. This drops them from ``html_js_files`` before the
builder reads it; they are still copied with the other static files.
"""

MODULE_DIRS = ("kernels/", "mech/")


def _is_module(entry):
    name = entry[0] if isinstance(entry, (tuple, list)) else entry
    return str(name).startswith(MODULE_DIRS)


def _drop_module_scripts(app, config):
    config.html_js_files = [f for f in config.html_js_files if not _is_module(f)]


def setup(app):
    app.connect("config-inited", _drop_module_scripts)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
