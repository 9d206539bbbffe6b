"""springscene: headless ball-and-spring scenes like VPython's, rendered off-screen."""
