"""Physical constants (SI, exact since the 2019 redefinition)."""

AVOGADRO = 6.02214076e23      # 1/mol
BOLTZMANN = 1.380649e-23      # J/K
