// placeholder: filled in by the level work
