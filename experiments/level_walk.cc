// placeholder: filled in by the level-walk work
