def generate_test_description():
    return ['not', 'a', 'launch description']
