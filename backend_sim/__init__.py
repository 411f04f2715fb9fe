"""The machine in software: main MCU, CNC MCU, motors, SD card, OLED and buttons. No Qt."""
