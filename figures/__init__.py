"""Plot scripts for the book: plain functions that take data (and axes) and draw.

Nothing here runs at import; Matplotlib is imported inside each module.
"""
