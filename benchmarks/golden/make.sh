#!/usr/bin/env bash
# usage: make.sh REPO_DIR OUT_DIR  — runs every golden job with the repo's .venv-test python
# The sample jobs whose outputs must not change under a refactor (lab with and without its hazard curve,
# lab in US units, pharmacy, the hospital (its site and building, no motion typed in), the km2010
# calibration and its application, the portfolio), run with REPO_DIR's .venv-test.
set -u
R=$1; O=$2; PY=$R/.venv-test/bin/python
rm -rf $O; mkdir -p $O
cd $R
$PY -m assess inventories/lab.xlsx --hazard 2in50 --out $O/lab --quiet > $O/lab.log 2>&1; echo "lab $?"
$PY -m assess inventories/lab.xlsx --hazard 2in50 --oq-hazard inventories/lab-hazard-curve.csv --out $O/lab-curve --quiet > $O/lab-curve.log 2>&1; echo "labcurve $?"
$PY -m assess inventories/pharmacy.xlsx --hazard DE --out $O/pharmacy --quiet > $O/pharmacy.log 2>&1; echo "pharm $?"
$PY -m assess inventories/hospital.xlsx --hazard DE --out $O/hospital --quiet > $O/hospital.log 2>&1; echo "hospital $?"
$PY -m assess inventories/lab.xlsx --hazard 2in50 --units us --out $O/lab-us --quiet > $O/lab-us.log 2>&1; echo "lab-us $?"
$PY -m assess calibrate inventories/km2010-prototypes.xlsx --measured inventories/km2010-measured.xlsx --out $O/calib > $O/calib.log 2>&1; echo "calib $?"
$PY -m assess inventories/km2010-prototypes.xlsx --hazard 2in50 --calibration $O/calib/calibration.json --out $O/km-cal --quiet > $O/kmcal.log 2>&1; echo "kmcal $?"
rm -rf /tmp/pf_$$; cp -r inventories/portfolio /tmp/pf_$$
$PY -m assess batch /tmp/pf_$$/portfolio.xlsx --out $O/portfolio --quiet > $O/portfolio.log 2>&1; echo "batch $?"
rm -rf /tmp/pf_$$
