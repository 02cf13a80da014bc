// placeholder: filled in by the triangle-index work
