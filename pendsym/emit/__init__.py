"""Emitters: kernels (Python, C), files laid out by Jinja, the LaTeX report."""
