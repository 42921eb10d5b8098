from scenewright.cli import run

run()
