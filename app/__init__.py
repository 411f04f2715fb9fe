"""Desktop controller for a small 3-axis CNC mill."""
