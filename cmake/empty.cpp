// Stands in for a library layer that has no sources yet.
