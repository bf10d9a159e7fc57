"""A portfolio of buildings (``assess batch``): each building's assessment and what the portfolio reports.

- :mod:`assess.portfolio.batch`: reads the portfolio, assesses every building through one cache, keeps a
  building's folder when nothing it depends on changed.
- :mod:`assess.portfolio.report`: portfolio.csv's rows, changes.csv and portfolio.html across buildings.
"""
