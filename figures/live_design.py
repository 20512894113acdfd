"""The live design figures of the synthesis chapter, written into the page at build time.

Each figure is drawn by its own page script (``book/_static/mech/design.js`` for rigid-body
guidance, ``fgdesign.js`` for function generation) run once here under Node, so the page
shows the right initial state before any script runs and the browser redraws it with the
same code as the reader drags. Node is the one the generator's JavaScript check uses
(``make setup`` installs it).
"""

import json
import subprocess
from pathlib import Path

__all__ = ["guidance_state", "live_figure"]

_MECH_JS = Path(__file__).resolve().parent.parent / "book" / "_static" / "mech"

_STYLE = """<style>
.mech-live-design svg{width:100%;max-height:32rem;border:1px solid #ccc;background:#fff;touch-action:none}
.mech-live-design .mech-pose{fill:#4c72b0;fill-opacity:.25;stroke:#4c72b0;vector-effect:non-scaling-stroke}
.mech-live-design .mech-handle{fill:#4c72b0;cursor:grab}
.mech-live-design rect.mech-handle{fill:#dd8452}
.mech-live-design .mech-pole{fill:#55a868}
.mech-live-design .mech-dyad,.mech-live-design .mech-design-linkage{stroke:#333;stroke-width:2;vector-effect:non-scaling-stroke}
.mech-live-design .mech-design-linkage{stroke:#c44e52;stroke-width:3}
.mech-live-design .mech-design-coupler{fill:#c44e52;fill-opacity:.2;stroke:#c44e52;vector-effect:non-scaling-stroke}
.mech-live-design .mech-centre-point{fill:#333}
.mech-live-design .mech-circle-point{fill:#fff;stroke:#333;vector-effect:non-scaling-stroke}
.mech-live-design .mech-centre-curve{stroke:#8172b3}
.mech-live-design .mech-circle-curve{stroke:#937860}
.mech-live-design .mech-error-curve{fill:none;stroke:#c44e52;stroke-width:2;vector-effect:non-scaling-stroke}
.mech-live-design .mech-fg-ghost{stroke:#4c72b0;stroke-opacity:.5;vector-effect:non-scaling-stroke}
.mech-live-design .mech-fg-axis,.mech-live-design .mech-fg-at{stroke:#999;vector-effect:non-scaling-stroke}
.mech-live-design table{font-size:.85em;margin:.4em 0}
.mech-live-design input[type=number]{width:6.5em}
.mech-live-design label{margin-right:.8em;white-space:nowrap}
</style>"""


def guidance_state(theta_deg, P, *, n=5):
    """The initial state of the guidance figure: five poses (angle in degrees, x, y), `n`
    of them in use, the first four-bar shown, two moving pivots for two or three poses."""
    poses = [[float(t), float(complex(p).real), float(complex(p).imag)] for t, p in zip(theta_deg, P)]
    xs, ys = [p[1] for p in poses], [p[2] for p in poses]
    cx, cy, size = sum(xs) / len(xs), sum(ys) / len(ys), max(max(xs) - min(xs), max(ys) - min(ys))
    pivots = [[round(cx - 0.4 * size, 3), round(cy - 0.6 * size, 3)], [round(cx + 0.4 * size, 3), round(cy - 0.5 * size, 3)]]
    return {"poses": poses, "n": int(n), "pick": 0, "t": 0.0, "pivots": pivots, "choose": [0.25, 0.75]}


def _node_render(module, state):
    from derivations import _node

    exe = _node.node()
    if exe is None:
        raise RuntimeError("node is not installed (make setup installs nodejs): the live figures are drawn by it")
    script = (f'import {{ render }} from "{(_MECH_JS / module).as_uri()}";\n'
              f"process.stdout.write(render({json.dumps(state)}));\n")
    done = subprocess.run([exe, "--input-type=module", "-"], input=script, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise RuntimeError(f"Node could not draw {module}: {done.stderr.strip()}")
    return done.stdout


def live_figure(module, state, *, depth=1, note="", kind=""):
    """The HTML of a live figure: its initial drawing (by `module`'s ``render`` under Node),
    its state, and the module script that makes it live. `depth` is the page's folder depth
    under the book's root (the script path is relative); `kind` is an extra class of the
    figure's element (``mech-live-fg`` for function generation)."""
    from html import escape

    body = _node_render(module, state)
    src = "../" * depth + f"_static/mech/{module}"
    note = f'<p class="mech-live-note">{note}</p>' if note else ""
    return (f"{_STYLE}\n<div class=\"mech-live-design{' ' + kind if kind else ''}\" data-state=\"{escape(json.dumps(state))}\">{body}</div>"
            f"{note}\n<script type=\"module\" src=\"{src}\"></script>")
