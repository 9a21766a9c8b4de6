"""The project layer: the modules of the checked tree (`modules.ModuleIndex`) and
what each one shows its importers (`summary.ModuleSummary`, built by `Project`)."""
