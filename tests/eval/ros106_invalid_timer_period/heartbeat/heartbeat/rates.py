"""Publishing rates of the heartbeat node, in Hz; 0 meant "as fast as possible" to someone."""
RATES = {'fast': 50.0, 'slow': 1.0, 'max': 0}


def period_of(mode):
    hz = RATES[mode]
    return 1.0 / hz if hz else 0.0
