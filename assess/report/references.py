"""The sources the report's text cites, in one list (the report's *References*).

Every author, standard and method the report, its flags and its notes name is
here, and nothing that none of them names (as plain text: the report links to nothing outside itself):
tests/report/test_report_references.py reads the templates and every message of the package for citations and checks
both directions. Each entry is as the module that implements it cites it (its
docstring's References); the DOI where the source has one.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Reference:
    """One source. ``cited_as`` is how the text names it (``"Konstantinidis & Makris"``, ``"ASCE 7-22"``):
    the surnames, or the standard's designation; ``year`` is '' for a standard cited by its designation."""

    cited_as: str
    year: str
    text: str
    doi: str = ""

    @property
    def url(self) -> str:
        return f"https://doi.org/{self.doi}" if self.doi else ""


REFERENCES = (
    Reference("Konstantinidis & Makris", "2010",
              "Konstantinidis, D., Makris, N. (2010). Experimental and analytical studies on the response of 1/4-scale "
              "models of freestanding laboratory equipment subjected to strong earthquake shaking. Bulletin of "
              "Earthquake Engineering 8(6):1457–1477.", "10.1007/s10518-010-9192-8"),
    Reference("Housner", "1963",
              "Housner, G. W. (1963). The behavior of inverted pendulum structures during earthquakes. Bulletin of "
              "the Seismological Society of America 53(2):403–417."),
    Reference("Shenton", "1996",
              "Shenton, H. W. (1996). Criteria for initiation of slide, rock, and slide-rock rigid-body modes. "
              "Journal of Engineering Mechanics 122(7):690–693.", "10.1061/(ASCE)0733-9399(1996)122:7(690)"),
    Reference("Makris & Roussos", "2000",
              "Makris, N., Roussos, Y. S. (2000). Rocking response of rigid blocks under near-source ground motions. "
              "Géotechnique 50(3):243–262.", "10.1680/geot.2000.50.3.243"),
    Reference("Zhang & Makris", "2001",
              "Zhang, J., Makris, N. (2001). Rocking response of free-standing blocks under cycloidal pulses. "
              "Journal of Engineering Mechanics 127(5):473–483.", "10.1061/(ASCE)0733-9399(2001)127:5(473)"),
    Reference("Newmark", "1965",
              "Newmark, N. M. (1965). Effects of earthquakes on dams and embankments. Géotechnique 15(2):139–160.",
              "10.1680/geot.1965.15.2.139"),
    Reference("Mavroeidis & Papageorgiou", "2003",
              "Mavroeidis, G. P., Papageorgiou, A. S. (2003). A mathematical representation of near-fault ground "
              "motions. Bulletin of the Seismological Society of America 93(3):1099–1131.", "10.1785/0120020100"),
    Reference("Dabaghi & Der Kiureghian", "2017",
              "Dabaghi, M., Der Kiureghian, A. (2017). Stochastic model for simulation of near-fault ground motions. "
              "Earthquake Engineering & Structural Dynamics 46(6):963–984.", "10.1002/eqe.2839"),
    Reference("Rezaeian & Der Kiureghian", "2008",
              "Rezaeian, S., Der Kiureghian, A. (2008). A stochastic ground motion model with separable temporal and "
              "spectral nonstationarities. Earthquake Engineering & Structural Dynamics 37(13):1565–1584.",
              "10.1002/eqe.831"),
    Reference("Gasparini & Vanmarcke", "1976",
              "Gasparini, D. A., Vanmarcke, E. H. (1976). SIMQKE: a program for artificial motion generation. "
              "Department of Civil Engineering, Massachusetts Institute of Technology, Cambridge, MA."),
    Reference("Boore", "2005",
              "Boore, D. M. (2005). On pads and filters: processing strong-motion data. Bulletin of the "
              "Seismological Society of America 95(2):745–750.", "10.1785/0120040160"),
    Reference("Moreau", "1988",
              "Moreau, J. J. (1988). Unilateral contact and dry friction in finite freedom dynamics. In: Nonsmooth "
              "Mechanics and Applications, CISM Courses and Lectures 302, Springer, 1–82.",
              "10.1007/978-3-7091-2624-0_1"),
    Reference("Jean", "1999",
              "Jean, M. (1999). The non-smooth contact dynamics method. Computer Methods in Applied Mechanics and "
              "Engineering 177(3–4):235–257.", "10.1016/S0045-7825(98)00383-1"),
    Reference("Miranda & Taghavi", "2005",
              "Miranda, E., Taghavi, S. (2005). Approximate floor acceleration demands in multistory buildings. I: "
              "Formulation. Journal of Structural Engineering 131(2):203–211.",
              "10.1061/(ASCE)0733-9445(2005)131:2(203)"),
    Reference("Chopra", "2012",
              "Chopra, A. K. (2012). Dynamics of Structures: Theory and Applications to Earthquake Engineering, "
              "4th ed. Pearson, Upper Saddle River, NJ."),
    Reference("Newmark", "1959",
              "Newmark, N. M. (1959). A method of computation for structural dynamics. Journal of the Engineering "
              "Mechanics Division, ASCE 85(EM3):67–94."),
    Reference("Clough & Johnston", "1966",
              "Clough, R. W., Johnston, S. B. (1966). Effect of stiffness degradation on earthquake ductility "
              "requirements. Proceedings of the 2nd Japan Earthquake Engineering Symposium, Tokyo, 227–232."),
    Reference("Takeda", "1970",
              "Takeda, T., Sozen, M. A., Nielsen, N. N. (1970). Reinforced concrete response to simulated "
              "earthquakes. Journal of the Structural Division, ASCE 96(ST12):2557–2573."),
    Reference("FEMA 356", "",
              "FEMA 356 (2000). Prestandard and Commentary for the Seismic Rehabilitation of Buildings. Federal "
              "Emergency Management Agency, Washington, DC. Table C1-3: structural performance levels and damage "
              "(drift of vertical elements)."),
    Reference("Baker", "2015",
              "Baker, J. W. (2015). Efficient analytical fragility function fitting using dynamic structural "
              "analysis. Earthquake Spectra 31(1):579–599.", "10.1193/021113EQS025M"),
    Reference("ASCE 7-16", "",
              "ASCE/SEI 7-16 (2017). Minimum Design Loads and Associated Criteria for Buildings and Other "
              "Structures. American Society of Civil Engineers, Reston, VA. Chapter 13: Seismic design requirements "
              "for nonstructural components.", "10.1061/9780784414248"),
    Reference("ASCE 7-22", "",
              "ASCE/SEI 7-22 (2022). Minimum Design Loads and Associated Criteria for Buildings and Other "
              "Structures. American Society of Civil Engineers, Reston, VA. Chapters 11–13 and 16.",
              "10.1061/9780784415788"),
    Reference("ASCE 41-17", "",
              "ASCE/SEI 41-17 (2017). Seismic Evaluation and Retrofit of Existing Buildings. American Society of "
              "Civil Engineers, Reston, VA. §2.3.3: nonstructural performance levels.", "10.1061/9780784414859"),
    Reference("ACI 318-19", "",
              "ACI 318-19 (2019). Building Code Requirements for Structural Concrete and Commentary. American "
              "Concrete Institute, Farmington Hills, MI. Chapter 17: Anchoring to concrete."),
    Reference("FEMA E-74", "",
              "FEMA E-74 (2012). Reducing the Risks of Nonstructural Earthquake Damage — A Practical Guide, 4th ed. "
              "Federal Emergency Management Agency, Washington, DC."),
    Reference("FEMA P-58", "",
              "FEMA P-58-1 (2018). Seismic Performance Assessment of Buildings, Volume 1 – Methodology, 2nd ed. "
              "Federal Emergency Management Agency, Washington, DC."),
)


def reference_rows() -> list[dict]:
    """The references as the report lists them: alphabetical by their first word, then year."""
    ordered = sorted(REFERENCES, key=lambda r: (r.text.split(",")[0].split(" ")[0].lower(), r.year, r.text))
    return [{"text": r.text, "doi": r.doi, "url": r.url} for r in ordered]
