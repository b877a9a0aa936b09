"""A headless turtlesim: the turtles, their motion and a canvas drawn into a PNG."""
