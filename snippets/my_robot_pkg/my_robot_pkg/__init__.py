"""Nodes of the example robot used throughout the textbook."""
