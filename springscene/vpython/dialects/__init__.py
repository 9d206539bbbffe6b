"""Which VPython a program was written for, and what its dialect needs to run on
springscene's VPython 7 interface: Web VPython's names and source leniencies, VPython 6's
``visual`` modules."""
