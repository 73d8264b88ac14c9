"""The hltl command line."""
