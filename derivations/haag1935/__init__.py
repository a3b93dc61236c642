"""Haag 1935, Théorie de la suspension élastique des pendules: the chapters rebuilt so far.

Each chapter is a tuple of sections (a section package's ``sections()`` or Section.of lines);
the report's headings group the Results of a chapter by equation number.


The registration (``MEMOIR``) is in :mod:`.registration`, imported when first asked for.
"""
from pendsym.plugin import lazy_package

__getattr__ = lazy_package(__name__)
