"""mech: a computer-algebra language for the configuration spaces of rigid mechanisms."""
