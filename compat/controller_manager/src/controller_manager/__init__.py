"""controller_manager command-line tools: spawner, unspawner, controller_manager."""
