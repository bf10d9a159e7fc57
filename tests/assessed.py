"""The assessment as the command hands it on: the pipeline's result with the advice in words.

The decisions stage gives numbers and kinds; the report makes the words (each item's action, what-if,
class reason, anchorage basis, cost note and the forces in kip) from them
(:func:`assess.report.advice.with_words`), as ``assess`` does before it writes or compares anything.
"""
from assess.assessment import pipeline
from assess.report.advice import with_words


def run_assessment(*args, **kwargs):
    """:func:`assess.assessment.pipeline.run_assessment`, then :func:`assess.report.advice.with_words`."""
    return with_words(pipeline.run_assessment(*args, **kwargs))
