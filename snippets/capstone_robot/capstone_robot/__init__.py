"""Nodes of the capstone robot system (chapter 7)."""
