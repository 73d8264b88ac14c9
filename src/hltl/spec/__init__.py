"""LTLf syntax, H-LTLf hierarchies, automata and monitors."""
