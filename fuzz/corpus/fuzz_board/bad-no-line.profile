gpio-chip gpiochip0
