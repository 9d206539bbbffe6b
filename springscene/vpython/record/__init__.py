"""A run as data: the recording written as a program runs, and read back
(docs/recording.md)."""
