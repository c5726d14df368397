"""Output: solutions turned into text, tables, charts, reports and files for other tools.

=============  ================================================================
``render``     text / JSON / CSV / Markdown views of solutions and assignments
``markdown``   escaping names from user files in Markdown
``growth``     the symbolic counts of ``count --symbolic`` as text, JSON, Markdown
``listing``    every valid robot with its configuration number (CSV, JSONL)
``chart``      what the charts show: radar chart (the article's Figure 9), bars,
               component matrix, as data
``plot``       the charts drawn by matplotlib (PNG, SVG, PDF files)
``svg``        the charts written straight as SVG (the studio's pages)
``report``     self-contained HTML and Markdown reports of a solved team
``uvl``        a team's design space as a UVL feature model
``batch``      many teams at once: parallel solving, summary, up-to-date skipping
=============  ================================================================

Nothing here decides anything: the numbers come from :mod:`solver.core` and
:mod:`solver.engines`.
"""
