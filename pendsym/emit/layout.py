"""The Jinja environment of pendsym/templates: templates lay out files and functions, and
never print an expression (the printers of :mod:`.kernels.printing` do)."""
from __future__ import annotations

import jinja2

ENV = jinja2.Environment(loader=jinja2.PackageLoader("pendsym", "templates"), autoescape=False,
                         keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True,
                         undefined=jinja2.StrictUndefined)


def lay_out(template: str, **ctx) -> str:
    """One template rendered with ctx."""
    return ENV.get_template(template).render(**ctx)
