"""The HTML edition: ``out/report.html`` and one annotated page per paper, from row dicts.

:mod:`~pendcli.output.html.report` writes the pages and prints them to PDF;
:mod:`~pendcli.output.html.rows` is all the edition reads of a row and the notes it writes,
:mod:`~pendcli.output.html.locate` finds where the paper's text prints a row,
:mod:`~pendcli.output.html.marks` places each row's marks on a page;
:mod:`~pendcli.output.html.paper` builds the paper page from its Jinja2 templates
(``templates/``, shipped as package data); :mod:`~pendcli.output.html.math` turns the OCR's
TeX into MathML, :mod:`~pendcli.output.html.match` tells which formula of a row's lines its
printed form is, :mod:`~pendcli.output.html.prose` joins the paragraphs the OCR cut, and
:mod:`~pendcli.output.html.graph` lays out the propagation graph.

May import: ``pendcli.base``, ``pendcli.data``, ``pendcli.verify``, the rest of ``pendcli.output``,
the registry inside functions; the run only for its result's type (``ReproduceResult``, under
``TYPE_CHECKING``). Never the CLI or a paper's own modules.
"""
