"""The shape of the code: import graph, layering, sizes of functions and files."""
