"""mech in Jupyter: the kernel (:mod:`mech.jupyter.kernel`, started as ``python -m mech.jupyter``)
and its installation (:mod:`mech.kernelspec`).  Needs the ``jupyter`` extra (ipykernel)."""
