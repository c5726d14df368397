"""Reading and writing files safely: the first wing every input passes through.

=============  ================================================================
``inputfile``  reading an input file with a size limit; located read failures
``yamlio``     safe YAML composition with line/column for every value
``reader``     typed, fault-collecting access to a composed document
``filekind``   which kind of file a document is: team, rule set or profile
``atomic``     writing output files atomically
=============  ================================================================

Not here: what the documents mean (:mod:`solver.core`), or what is written into them
(:mod:`solver.reporting`). This wing imports nothing of the project but :mod:`solver.errors`
and :mod:`solver.untrusted`.
"""
