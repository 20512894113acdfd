"""Derivation notebooks (MyST Markdown) and the code generator that turns them into NumPy."""
