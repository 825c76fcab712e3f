int dummy_test_contact;
