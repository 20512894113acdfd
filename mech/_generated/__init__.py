"""Generated NumPy code. Never edit by hand: run ``python -m derivations``.

Only ``mech/<area>/`` modules import from here.
"""
