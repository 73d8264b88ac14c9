"""Exact search over the unified graph of joint robot states, bindings and monitor states."""
