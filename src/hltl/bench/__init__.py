"""Benchmark code behind ``hltl bench …``: corpora, measurements and their reports."""
