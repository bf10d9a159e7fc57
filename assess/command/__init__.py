"""What the ``assess`` command needs around the assessment: its jobs, files and folders, Ctrl-C.

- :mod:`assess.command.job`: the jobs the commands run (``assess WORKBOOK``, ``assess batch``,
  ``assess calibrate``): inputs checked, the engine's runner opened and closed, the result returned.
- :mod:`assess.command.cache`: the engine results kept between runs (a runner in front of the engine).
- :mod:`assess.command.output`: the files of a run, made in memory from its result.
- :mod:`assess.command.folders`: output folders written whole or not at all.
- :mod:`assess.command.interrupts`: Ctrl-C and a closed pipe, and the exit codes that say what stopped a run.
- :mod:`assess.command.site_option`: ``--oq-site`` as typed, before argparse sees it.
- :mod:`assess.command.option_values`: what the options take (argparse types), each wrong value refused.

The command line itself is :mod:`assess.cli`. This file imports nothing: :mod:`assess.cli` reads
``site_option``, ``option_values``, ``folders`` and ``interrupts`` before it imports the core.
"""
