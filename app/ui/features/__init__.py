"""The window's side of issue 10: the feature job dialog and the point-list import step."""
