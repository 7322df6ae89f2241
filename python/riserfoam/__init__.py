"""riserFoam's Python package: what the tests, the validation, the
benchmarks and the tutorials' plot scripts share.

  foamfields  the plain ASCII OpenFOAM files: vector and scalar lists
              (lagrangian fields, internal fields, patch values), FoamFile
              headers, a volVectorField from a function, dictionary edits
  tables      the library's text tables (particles.dat, contacts.dat,
              sweep.dat, ...) read by the column names in their header
  carrier     the analytic riser carrier: axis position, riser velocity,
              Poiseuille speed about the moving axis
  cases       case setup: a tutorial copied to a scratch folder and edited,
              the riser mesh, the wall-contact test cases, running commands

Scripts find the package through PYTHONPATH, which etc/bootstrap's
environment file sets to the repository's python/ folder.

SPDX-License-Identifier: GPL-3.0-or-later
"""
