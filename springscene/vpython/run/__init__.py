"""A VPython program run: headless, in a supervised child process, to its video, page and
pictures, put in place only when whole."""
