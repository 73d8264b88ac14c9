"""Scene model, world state, context labelling and projection."""
