// Placeholder so the assets library has a source until its first real file lands; delete when one exists.
