"""The Snakemake workflow (Snakefile, workflow/): rules, plans, scripts, notebooks, the full run."""
