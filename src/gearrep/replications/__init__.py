"""One module per replicated paper: each exposes ``run(params)`` returning tables and
``checks(tables, published)`` returning check records (see :mod:`gearrep.checks`)."""
