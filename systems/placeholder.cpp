// Placeholder so the systems library has a source until its first real file lands; delete when one exists.
